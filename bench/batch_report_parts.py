#!/usr/bin/env python3
"""Synthetic shard reports for the report-merge benchmark (BENCHMARKS "Merging
the shards' reports", issue 18): the reports `procex batch --shard i/N` writes
for a batch of B buildings, one file per shard, each entry with the members a
batch gives it. Deterministic. Merge them with
`procex merge PREFIX*.json -o OUT.glb --report OUT.json`.

  bench/batch_report_parts.py B N PREFIX
"""
import json
import sys


def entry(i):
    status = ("ok", "ok", "ok", "refused", "failed")[i % 5]
    return {"index": i, "id": "way/%d" % (1000003 * i % 999983), "status": status,
            "reason": "a ring needs 4 positions" if status == "refused" else "",
            "warnings": ["Roof: a 0.2 m edge kept"] if i % 7 == 0 else [],
            "meshes": 1 + i % 3, "faces": 40 + i % 97,
            "faces_per_tag": {"wall": 20 + i % 13, "roof": i % 11, "window": i % 5},
            "bounds": {"min": [40.0 * (i % 1000), 40.0 * (i // 1000), 0.0],
                       "max": [40.0 * (i % 1000) + 12.5, 40.0 * (i // 1000) + 9.25, 11.0 + i % 4]},
            "volume": 1237.5 + i % 17, "placed": {"window": i % 23, "door": 1}, "ms": 0.25 * (i % 9)}


def main():
    buildings, shards, prefix = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    for s in range(shards):
        with open("%s%d.json" % (prefix, s), "w") as f:  # entry by entry: a million fit in little memory
            head = {"recipe": "samples/city.pxg", "footprints": "city.geojson", "output": "part%d.glb" % s,
                    "shard": {"index": s, "count": shards, "recipe": "3f2a", "footprints": "9b1c"}}
            f.write(json.dumps(head, indent=1)[:-2] + ',\n "buildings": [')
            for n, i in enumerate(range(s, buildings, shards)):
                f.write(("," if n else "") + "\n  " + json.dumps(entry(i)))
            f.write('\n ],\n "summary": {}\n}\n')


if __name__ == "__main__":
    main()
