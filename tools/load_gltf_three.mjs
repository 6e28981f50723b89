// Loads one .glb with three.js's GLTFLoader (as a browser would) and prints
// what it found as JSON: one entry per primitive with its node's building id, its tag
// (extras), material and triangle count. Exit code 1 if loading fails.
import { readFileSync } from 'node:fs';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const file = process.argv[2];
const buffer = readFileSync(file);
const data = buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + buffer.byteLength);
new GLTFLoader().parse(data, '', (gltf) => {
  const meshes = [];
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    meshes.push({
      name: o.name,
      building: o.userData.building ?? o.parent?.userData?.building,
      tag: o.geometry.userData.tag,
      material: o.material.name,
      triangles: o.geometry.index ? o.geometry.index.count / 3 : 0,
      vertices: o.geometry.attributes.position.count,
      normals: o.geometry.attributes.normal !== undefined,
    });
  });
  console.log(JSON.stringify({ nodes: gltf.scene.children.length, meshes }, null, 1));
}, (error) => {
  console.error(`${file}: ${error.message ?? error}`);
  process.exit(1);
});
