// Validates glTF/GLB files with the Khronos glTF-Validator (npm gltf-validator): every one under a
// folder, or those listed in a file (one path a line) given as @LIST; one JSON line per file: error,
// warning and info counts, the codes, and each error's message and JSON pointer. Used by
// tools/warnings/run.sh and tools/validator/oracle.py. Usage: node validate.js FOLDER|@LIST
const validator = require('gltf-validator');
const fs = require('fs');
const path = require('path');
function walk(dir, out) {
  for (const e of fs.readdirSync(dir, {withFileTypes: true})) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) walk(p, out);
    else if (/\.(gltf|glb)$/.test(e.name)) out.push(p);
  }
  return out;
}
(async () => {
  const arg = process.argv[2];
  const files = arg.startsWith('@') ? fs.readFileSync(arg.slice(1), 'utf8').split('\n').filter(l => l) : walk(arg, []).sort();
  for (const file of files) {
    const data = new Uint8Array(fs.readFileSync(file));
    try {
      const report = await validator.validateBytes(data, {
        uri: file, maxIssues: 1000,
        externalResourceFunction: (uri) => new Promise((resolve, reject) => {
          fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, d) => err ? reject(err.toString()) : resolve(new Uint8Array(d)));
        })});
      const codes = {};
      for (const m of report.issues.messages) { const k = ['E','W','I','H'][m.severity] + ':' + m.code; codes[k] = (codes[k] || 0) + 1; }
      const errorMessages = report.issues.messages.filter(m => m.severity === 0).slice(0, 5).map(m => m.code + ' ' + (m.pointer || '') + ': ' + m.message);
      console.log(JSON.stringify({file, errors: report.issues.numErrors, warnings: report.issues.numWarnings, infos: report.issues.numInfos, hints: report.issues.numHints, codes, errorMessages}));
    } catch (e) { console.log(JSON.stringify({file, failed: String(e)})); }
  }
})();
