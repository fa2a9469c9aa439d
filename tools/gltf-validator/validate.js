// Validates a .gltf file and the files it references with the Khronos glTF validator.
// Usage: node validate.js <validator module folder> <file.gltf>
// Prints the validator's report (JSON) and exits 0 when it found no errors, 1 when it did,
// 2 when the file could not be read.
'use strict';
const fs = require('fs');
const path = require('path');

const [modulePath, file] = process.argv.slice(2);
const validator = require(modulePath);

let bytes;
try {
  bytes = new Uint8Array(fs.readFileSync(file));
} catch (error) {
  console.error(`${file}: ${error.message}`);
  process.exit(2);
}
const folder = path.dirname(file);
validator.validateBytes(bytes, {
  uri: path.basename(file),
  maxIssues: 100,
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    fs.readFile(path.join(folder, decodeURIComponent(uri)), (error, data) => {
      if (error) reject(error.toString()); else resolve(new Uint8Array(data));
    });
  }),
}).then((report) => {
  console.log(JSON.stringify(report, null, 2));
  process.exit(report.issues.numErrors > 0 ? 1 : 0);
}, (error) => {
  console.error(`${file}: ${error}`);
  process.exit(2);
});
