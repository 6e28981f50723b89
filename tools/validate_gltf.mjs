// Runs the Khronos glTF validator on one .glb and prints its report as JSON.
// Exit code: 0 without errors, 1 with errors, 2 if the file cannot be read.
import { readFileSync } from 'node:fs';
import validator from 'gltf-validator';

const file = process.argv[2];
let bytes;
try {
  bytes = new Uint8Array(readFileSync(file));
} catch (e) {
  console.error(`${file}: ${e.message}`);
  process.exit(2);
}
const report = await validator.validateBytes(bytes, { maxIssues: 100 });
console.log(JSON.stringify({ issues: report.issues, info: report.info }, null, 1));
process.exit(report.issues.numErrors > 0 ? 1 : 0);
