// Validates every glTF/GLB under a folder with the Khronos glTF-Validator (npm gltf-validator);
// one JSON line per file: error, warning and info counts and the codes. Used by run.sh.
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
  for (const file of walk(process.argv[2], []).sort()) {
    const data = new Uint8Array(fs.readFileSync(file));
    try {
      const report = await validator.validateBytes(data, {
        uri: file, maxIssues: 1000,
        externalResourceFunction: (uri) => new Promise((resolve, reject) => {
          fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, d) => err ? reject(err.toString()) : resolve(new Uint8Array(d)));
        })});
      const codes = {};
      for (const m of report.issues.messages) { const k = ['E','W','I','H'][m.severity] + ':' + m.code; codes[k] = (codes[k] || 0) + 1; }
      console.log(JSON.stringify({file, errors: report.issues.numErrors, warnings: report.issues.numWarnings, infos: report.issues.numInfos, hints: report.issues.numHints, codes}));
    } catch (e) { console.log(JSON.stringify({file, failed: String(e)})); }
  }
})();
