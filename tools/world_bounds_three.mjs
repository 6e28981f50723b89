// Loads one .glb with three.js's GLTFLoader (as a browser would) and prints
// the world-space bounding box of every primitive as JSON, with its tag
// (extras): what a viewer shows, after every node matrix above it is applied.
// Exit code 1 if loading fails.
import { readFileSync } from 'node:fs';
import { Box3 } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const file = process.argv[2];
const buffer = readFileSync(file);
const data = buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + buffer.byteLength);
new GLTFLoader().parse(data, '', (gltf) => {
  gltf.scene.updateMatrixWorld(true);
  const meshes = [];
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    const box = new Box3().setFromObject(o, true);
    meshes.push({ tag: o.geometry.userData.tag, min: box.min.toArray(), max: box.max.toArray() });
  });
  console.log(JSON.stringify({ meshes }, null, 1));
}, (error) => {
  console.error(`${file}: ${error.message ?? error}`);
  process.exit(1);
});
