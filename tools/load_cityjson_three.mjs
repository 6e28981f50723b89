// Loads one CityJSON file with cityjson-threejs-loader (the three.js loader
// CityJSON viewers use, e.g. ninja) as a browser would, and prints what it
// made as JSON: per CityObject and LoD, the triangles per semantic surface
// type, their area, and the bounds of its vertices in the file's own
// coordinates (the loader's centring matrix taken off again). Exit code 1 if
// loading fails.
import { readFileSync } from 'node:fs';
import { register } from 'node:module';

register('./resolve_js_extension.mjs', import.meta.url);
const { Matrix4, Vector3 } = await import('three');
// The loader and its in-thread parser themselves: the package's index also
// loads its TextureManager, which imports sRGBEncoding, gone from three since
// r162 (procex writes no textures, so nothing else is lost).
const { CityJSONLoader } = await import('cityjson-threejs-loader/src/base/CityJSONLoader.js');
const { CityJSONParser } = await import('cityjson-threejs-loader/src/parsers/CityJSONParser.js');

const file = process.argv[2];
let data;
try {
  data = JSON.parse(readFileSync(file, 'utf8'));
} catch (error) {
  console.error(`${file}: ${error.message}`);
  process.exit(1);
}
const parser = new CityJSONParser();
const loader = new CityJSONLoader(parser);
loader.load(data);
const back = new Matrix4().copy(loader.matrix).invert();
const ids = Object.keys(data.CityObjects);
const surfaceTypes = Object.keys(parser.surfaceColors);
const objects = {};
loader.scene.traverse((o) => {
  if (!o.isCityObjectMesh) return;
  const g = o.geometry;
  const pos = g.getAttribute('position'), obj = g.getAttribute('objectid');
  const surf = g.getAttribute('surfacetype'), lod = g.getAttribute('lodid');
  const p = [new Vector3(), new Vector3(), new Vector3()];
  for (let t = 0; t * 3 < pos.count; ++t) {
    const i = t * 3;
    for (let k = 0; k < 3; ++k) p[k].fromBufferAttribute(pos, i + k).applyMatrix4(back);
    const id = ids[obj.getX(i)];
    const level = parser.lods[lod.getX(i)];
    const type = surface(surf.getX(i));
    const entry = ((objects[id] ??= { type: data.CityObjects[id]?.type, lods: {} }).lods[level] ??=
      { triangles: {}, area: {}, min: [Infinity, Infinity, Infinity], max: [-Infinity, -Infinity, -Infinity] });
    entry.triangles[type] = (entry.triangles[type] ?? 0) + 1;
    const area = new Vector3().subVectors(p[1], p[0]).cross(new Vector3().subVectors(p[2], p[0])).length() / 2;
    entry.area[type] = (entry.area[type] ?? 0) + area;
    for (const v of p)
      for (let k = 0; k < 3; ++k)
        entry.min[k] = Math.min(entry.min[k], v.getComponent(k)), entry.max[k] = Math.max(entry.max[k], v.getComponent(k));
  }
});
function surface(index) { return index >= 0 ? surfaceTypes[index] : 'none'; }
console.log(JSON.stringify({ referenceSystem: data.metadata?.referenceSystem, objects }, null, 1));
