# Reads the georeference of a .glb procex wrote, as a GIS script would: the
# scene's extras.crs (WKT2) through GDAL/OSR and PROJ, and per building node
# its translation and extras.origin (double precision, straight from the JSON
# chunk) and its meshes' bounds (the POSITION accessors' min/max), placed in
# that CRS by the rule core/io/gltf_crs.h states: east = x, north = -z,
# up = y. Writes JSON: the CRS (and whether it is the same as one given), and
# per building its bounds in the CRS (east, north, up), its bounds' centre in
# longitude/latitude (PROJ through OSR), and whether its extras.origin is its
# translation.
#
#   python3 tools/read_glb_georeference.py FILE.glb "CRS procex was given, or ''" OUT.json
import json
import struct
import sys

from osgeo import osr

osr.UseExceptions()


def json_chunk(path):
    with open(path, 'rb') as f:
        data = f.read()
    magic, version, length = struct.unpack_from('<4sII', data, 0)
    if magic != b'glTF' or version != 2 or length != len(data):
        raise SystemExit(f'{path}: not a glTF 2.0 binary file')
    chunk_length, chunk_type = struct.unpack_from('<II', data, 12)
    if chunk_type != 0x4E4F534A:  # JSON
        raise SystemExit(f'{path}: the first chunk is not JSON')
    return json.loads(data[20:20 + chunk_length])


def mesh_bounds(gltf, node, low, high, offset):
    # Building nodes hold only a translation; their children (placed meshes) are left out.
    if 'mesh' not in node:
        return
    for prim in gltf['meshes'][node['mesh']]['primitives']:
        acc = gltf['accessors'][prim['attributes']['POSITION']]
        for k in range(3):
            low[k] = min(low[k], offset[k] + acc['min'][k])
            high[k] = max(high[k], offset[k] + acc['max'][k])


def main():
    path, crs_text, out = sys.argv[1:4]
    gltf = json_chunk(path)
    scene = gltf['scenes'][gltf.get('scene', 0)]
    wkt = scene.get('extras', {}).get('crs')
    result = {'crs': wkt, 'buildings': {}}
    if wkt is None:
        json.dump(result, open(out, 'w'), indent=1)
        return
    srs = osr.SpatialReference()
    srs.ImportFromWkt(wkt)
    srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    if crs_text:
        given = osr.SpatialReference()
        given.SetFromUserInput(crs_text)
        result['crs_same'] = bool(srs.IsSame(given))
    result['projected_metres'] = bool(srs.IsProjected() and srs.GetLinearUnits() == 1.0)
    wgs84 = osr.SpatialReference()
    wgs84.ImportFromEPSG(4326)
    wgs84.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    to_lonlat = osr.CoordinateTransformation(srs, wgs84)
    for index in scene['nodes']:
        node = gltf['nodes'][index]
        extras = node.get('extras', {})
        if 'building' not in extras:
            continue
        if any(k in node for k in ('matrix', 'rotation', 'scale')):
            raise SystemExit(f'{path}: node {index} is not placed by a translation alone')
        t = node.get('translation', [0.0, 0.0, 0.0])
        origin = extras.get('origin', [0.0, 0.0, 0.0])
        low, high = [float('inf')] * 3, [float('-inf')] * 3
        mesh_bounds(gltf, node, low, high, t)
        # glTF (x, y, z) -> the CRS's (east, north, up).
        east_north_up = lambda p: [p[0], -p[2], p[1]]
        lo, hi = east_north_up(low), east_north_up(high)
        lo[1], hi[1] = hi[1], lo[1]  # north = -z swaps the ends
        lon, lat, _ = to_lonlat.TransformPoint((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, 0.0)
        result['buildings'][node.get('name', str(index))] = {
            'min': lo, 'max': hi, 'lonlat': [lon, lat],
            'origin_is_translation': east_north_up(t) == origin,
        }
    json.dump(result, open(out, 'w'), indent=1)


if __name__ == '__main__':
    main()
