// Validates a .glb / .gltf with the Khronos glTF validator (npm "gltf-validator") and prints one
// summary line plus every error and warning. Exit 0 when the validator reports zero errors, 1
// when it reports any, 2 when the file cannot be read or the validator is missing.
//
//   node validate_gltf.mjs MODULES_DIR FILE [--max-warnings N]
//
// MODULES_DIR is the folder that holds node_modules/gltf-validator (scripts/setup runs npm ci
// there: the build tree, not the source tree).
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
import path from 'node:path';

const [modulesDir, file, ...rest] = process.argv.slice(2);
if (!modulesDir || !file) {
  console.error('usage: node validate_gltf.mjs MODULES_DIR FILE [--max-warnings N]');
  process.exit(2);
}
let maxWarnings = Infinity;
if (rest[0] === '--max-warnings') maxWarnings = Number(rest[1]);

let validator;
try {
  validator = createRequire(path.resolve(modulesDir) + '/')('gltf-validator');
} catch (e) {
  console.error(`error: gltf-validator is not installed in ${modulesDir} (run scripts/setup)`);
  process.exit(2);
}
let bytes;
try {
  bytes = new Uint8Array(readFileSync(file));
} catch (e) {
  console.error(`error: ${file}: ${e.message}`);
  process.exit(2);
}
const report = await validator.validateBytes(bytes, {
  uri: path.basename(file),
  maxIssues: 0,
  externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}`)),
});
const issues = report.issues;
const info = report.info || {};
console.log(`${path.basename(file)}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
            `${issues.numInfos} infos, ${issues.numHints} hints; ` +
            `${info.animationCount ?? 0} animations, ${info.materialCount ?? 0} materials, ` +
            `${info.drawCallCount ?? 0} draw calls, ${info.totalVertexCount ?? 0} vertices, ` +
            `skins ${info.hasSkins}, morph targets ${info.hasMorphTargets} ` +
            `(validator ${report.validatorVersion})`);
for (const message of issues.messages) {
  if (message.severity <= 1 || process.env.GLTF_VALIDATOR_ALL) {
    const kind = ['error', 'warning', 'info', 'hint'][message.severity];
    console.log(`  ${kind} ${message.code} ${message.pointer ?? ''}: ${message.message}`);
  }
}
process.exit(issues.numErrors === 0 && issues.numWarnings <= maxWarnings ? 0 : 1);
