// Joins the glTF-Validator's report (validate.js, one JSON line per file) with the warning lines
// `candela render` printed for each file (a folder of FILE.txt, one per model) into the markdown
// table of docs/scenes.md. Usage: node table.js VALIDATOR.jsonl LINES_DIR MODELS_DIR
const fs = require('fs');
const path = require('path');
const [validatorFile, linesDir, modelsDir] = process.argv.slice(2);
const rows = fs.readFileSync(validatorFile, 'utf8').trim().split('\n').map(l => JSON.parse(l));
console.log('| file | candela: warning lines | glTF-Validator: errors / warnings / infos (codes) |');
console.log('|---|---|---|');
for (const r of rows) {
  const rel = path.relative(modelsDir, r.file);
  const txt = path.join(linesDir, rel.replace(/[\/]/g, '__') + '.txt');
  const lines = fs.existsSync(txt) ? fs.readFileSync(txt, 'utf8').split('\n').filter(l => l.includes('warning:')) : null;
  const ours = lines === null ? '?' : lines.length === 0 ? '0'
      : lines.length + ': ' + lines.map(l => '`' + l.replace(/^candela: warning: [^:]*: /, '').replace(/\|/g, '\\|') + '`').join('; ');
  const codes = Object.entries(r.codes || {}).filter(([k]) => !k.startsWith('H:')).map(([k, n]) => k + ' ×' + n).join(', ');
  console.log(`| ${rel} | ${ours} | ${r.errors} / ${r.warnings} / ${r.infos}${codes ? ' (' + codes + ')' : ''} |`);
}
