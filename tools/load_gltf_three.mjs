// Loads one .glb with three.js's GLTFLoader (as a browser would) and prints
// what it found as JSON: the scene's top nodes (name, position, extras), and
// one entry per primitive with its node's building id, its tag (extras), its
// instance's tag if placed with one,
// material (its name, base colour, roughness, metalness, whether it shows a
// texture and the texture's repeat), triangle
// count, whether it has normals (and how far from flat they are) and texture
// coordinates,
// and its world bounds (three.js is +Y up, as glTF). Exit code 1 if loading fails.
import { readFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { Box3, Vector3 } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

// Node.js has no image decoding of a browser's: GLTFLoader's own path for an
// embedded image (a blob URL, fetched, then createImageBitmap) runs with the
// global names it expects, the PNG decoded by pngjs. An image that is not a
// valid PNG fails the load.
globalThis.self = globalThis;
globalThis.createImageBitmap = async (blob) => {
  const png = PNG.sync.read(Buffer.from(await blob.arrayBuffer()));
  return { width: png.width, height: png.height, data: png.data, close() {} };
};

// How far a primitive's normals are from flat normals facing as its triangles
// wind (counter-clockwise seen from outside, as glTF says): the largest
// 1 - cos(angle) between a corner's normal and its triangle's, 2 where a
// corner has no normal. Triangles under 0.01 m² are left out: a sliver's own
// direction, from float32 positions, is off by up to a degree.
function normalError(geometry) {
  const pos = geometry.attributes.position, normal = geometry.attributes.normal, index = geometry.index;
  if (!normal || !index) return 2;
  const p = [new Vector3(), new Vector3(), new Vector3()], n = new Vector3(), face = new Vector3();
  let worst = 0;
  for (let t = 0; t < index.count; t += 3) {
    for (let k = 0; k < 3; ++k) p[k].fromBufferAttribute(pos, index.getX(t + k));
    face.subVectors(p[1], p[0]).cross(n.subVectors(p[2], p[0]));
    if (face.length() / 2 < 0.01) continue;
    face.normalize();
    for (let k = 0; k < 3; ++k) worst = Math.max(worst, 1 - n.fromBufferAttribute(normal, index.getX(t + k)).normalize().dot(face));
  }
  return worst;
}

const file = process.argv[2];
const buffer = readFileSync(file);
const data = buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + buffer.byteLength);
new GLTFLoader().parse(data, '', (gltf) => {
  gltf.scene.updateMatrixWorld(true);
  const meshes = [];
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    meshes.push({
      name: o.name,
      building: o.userData.building ?? o.parent?.userData?.building,
      tag: o.geometry.userData.tag,
      // A placed mesh's instance tag (its node's extras; a node of several
      // primitives is the parent of their meshes).
      node_tag: o.userData.tag ?? o.parent?.userData?.tag ?? null,
      material: o.material.name,
      triangles: o.geometry.index ? o.geometry.index.count / 3 : 0,
      vertices: o.geometry.attributes.position.count,
      normals: o.geometry.attributes.normal !== undefined,
      normal_error: normalError(o.geometry),
      uvs: o.geometry.attributes.uv !== undefined,
      // The _TAG attribute (three.js lower-cases it) named through the asset's tag list.
      tag_attribute: o.geometry.attributes._tag
        ? [...new Set(o.geometry.attributes._tag.array)].map((i) => gltf.asset.extras.tags[i]) : null,
      texture: o.material.map != null,
      texture_size: o.material.map ? [o.material.map.image.width, o.material.map.image.height] : null,
      colour: o.material.color.toArray(),
      roughness: o.material.roughness,
      metalness: o.material.metalness,
      // KHR_texture_transform's scale, as three.js applies it to the map.
      texture_repeat: o.material.map ? o.material.map.repeat.toArray() : null,
      min: new Box3().setFromObject(o, true).min.toArray(),
      max: new Box3().setFromObject(o, true).max.toArray(),
    });
  });
  const top = gltf.scene.children.map((n) => ({ name: n.name, position: n.position.toArray(), extras: n.userData }));
  console.log(JSON.stringify({ nodes: gltf.scene.children.length, top, meshes }, null, 1));
}, (error) => {
  console.error(`${file}: ${error.message ?? error}`);
  process.exit(1);
});
