#!/usr/bin/env node
// The reference for Candela's framing (docs/scenes.md, "Framing"): how much of a 512x512 thumbnail
// <model-viewer> covers, with its default camera, for sample models. Opt-in, tests only: needs npm
// (`npm ci` here installs the pinned model-viewer, puppeteer-core and pngjs) and Debian's chromium.
//   cd tools/model-viewer && npm ci && node measure.js [--models DIR] [--out DIR] [NAME ...]
// DIR defaults: ../../../shared/assets/models and ./out. Writes OUT/NAME.png and OUT/coverage.json
// (coverage: the share of pixels with alpha > 0; bbox: [minX, minY, maxX, maxY]), which
// tests/data/model-viewer/coverage.json holds a copy of.
'use strict';
const http = require('http');
const fs = require('fs');
const path = require('path');
const puppeteer = require('puppeteer-core');
const { PNG } = require('pngjs');
const { execFileSync } = require('child_process');

const ROOT = __dirname;  // serves page.html and node_modules; /models/ from MODELS_DIR
function option(name, fallback) {
  const i = process.argv.indexOf(name);
  if (i < 0) return fallback;
  const value = process.argv[i + 1];
  process.argv.splice(i, 2);
  return path.resolve(value);
}
const MODELS_DIR = option('--models', path.resolve(ROOT, '../../../shared/assets/models'));
const OUT = option('--out', path.join(ROOT, 'out'));
const W = 512, H = 512;

const ANIMATED = ['SimpleMorph', 'BoxAnimated', 'CesiumMan', 'RiggedFigure', 'RecursiveSkeletons', 'Fox', 'AnimatedCube', 'AnimatedMorphCube'];
const STATIC = ['Box', 'BoxTextured', 'BoxVertexColors', 'DamagedHelmet', 'Duck', 'Avocado', 'WaterBottle', 'Suzanne', 'ToyCar', 'SheenChair', 'OrientationTest', 'MetalRoughSpheresNoTextures'];

function findModel(name) {
  // prefer glTF-Binary/NAME.glb, else glTF/NAME.gltf
  for (const rel of [`${name}/glTF-Binary/${name}.glb`, `${name}/glTF/${name}.gltf`]) {
    if (fs.existsSync(path.join(MODELS_DIR, rel))) return rel;
  }
  throw new Error('model not found: ' + name);
}

const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.gltf': 'model/gltf+json',
  '.glb': 'model/gltf-binary', '.bin': 'application/octet-stream', '.png': 'image/png', '.jpg': 'image/jpeg',
  '.jpeg': 'image/jpeg', '.ktx2': 'image/ktx2', '.webp': 'image/webp', '.json': 'application/json', '.map': 'application/json' };

function startServer() {
  const server = http.createServer((req, res) => {
    const p = path.normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)).replace(/^(\.\.[\/\\])+/, '');
    const file = p.startsWith('/models/') ? path.join(MODELS_DIR, p.slice('/models/'.length)) : path.join(ROOT, p);
    fs.readFile(file, (err, data) => {
      if (err) { res.writeHead(404); res.end('not found'); return; }
      res.writeHead(200, { 'Content-Type': MIME[path.extname(file).toLowerCase()] || 'application/octet-stream' });
      res.end(data);
    });
  });
  return new Promise(r => server.listen(0, '127.0.0.1', () => r(server)));
}

function analyze(buf) {
  const png = PNG.sync.read(buf);
  const { width, height, data } = png;
  let n = 0, minX = Infinity, maxX = -1, minY = Infinity, maxY = -1;
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) {
    if (data[(y * width + x) * 4 + 3] > 0) {
      n++;
      if (x < minX) minX = x; if (x > maxX) maxX = x;
      if (y < minY) minY = y; if (y > maxY) maxY = y;
    }
  }
  return { width, height, covered: n, coverage: n / (width * height), bbox: n ? [minX, minY, maxX, maxY] : null };
}

(async () => {
  const only = process.argv.slice(2);
  const names = [...ANIMATED, ...STATIC].filter(n => !only.length || only.includes(n));
  fs.mkdirSync(OUT, { recursive: true });
  const server = await startServer();
  const port = server.address().port;
  const browser = await puppeteer.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run',
      '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
      '--disable-gpu-vsync', '--hide-scrollbars'],
  });
  const chromium = await browser.version();
  const mvVersion = require('@google/model-viewer/package.json').version;
  const results = { modelViewerVersion: mvVersion, chromium, width: W, height: H,
    camera: 'model-viewer defaults (camera-orbit 0deg 75deg 105%, field-of-view auto=30deg framed, camera-target auto)',
    models: {} };
  for (const name of names) {
    const file = findModel(name);
    const page = await browser.newPage();
    await page.setViewport({ width: W, height: H, deviceScaleFactor: 1 });
    const logs = [];
    page.on('console', m => logs.push(m.type() + ': ' + m.text()));
    page.on('pageerror', e => logs.push('pageerror: ' + e.message));
    const t0 = Date.now();
    try {
      await page.goto(`http://127.0.0.1:${port}/page.html?src=${encodeURIComponent('/models/' + file)}`, { waitUntil: 'load' });
      await page.waitForFunction('window.__loaded', { timeout: 120000 });
      await page.evaluate('window.__loaded');
      await page.waitForFunction(() => window.__mv.modelIsVisible === true, { timeout: 120000, polling: 100 });
      // let the camera settle and a few frames render; then capture twice and require stability
      let prev = null, cur = null, stable = false;
      for (let i = 0; i < 10 && !stable; i++) {
        await page.evaluate(() => new Promise(r => { let k = 0; const f = () => (++k >= 5 ? r() : requestAnimationFrame(f)); requestAnimationFrame(f); }));
        await new Promise(r => setTimeout(r, 300));
        cur = await page.evaluate(() => window.__mv.toDataURL('image/png'));
        stable = prev !== null && prev === cur;
        prev = cur;
      }
      const info = await page.evaluate(() => {
        const mv = window.__mv;
        const canvases = [...mv.shadowRoot.querySelectorAll('canvas')].map(c => [c.width, c.height, c.className]);
        return { cameraOrbit: mv.getCameraOrbit().toString(), fov: mv.getFieldOfView(), target: mv.getCameraTarget().toString(),
          dims: mv.getDimensions().toString(), canvases, events: window.__events.map(e => e.type) };
      });
      const buf = Buffer.from(cur.split(',')[1], 'base64');
      fs.writeFileSync(path.join(OUT, name + '.png'), buf);
      const a = analyze(buf);
      results.models[name] = { file, animated: ANIMATED.includes(name), coverage: +a.coverage.toFixed(6), bbox: a.bbox,
        pngSize: [a.width, a.height], stable, cameraOrbit: info.cameraOrbit, fieldOfViewDeg: +info.fov.toFixed(4),
        cameraTarget: info.target, dimensions: info.dims };
      console.log(`${name.padEnd(28)} ${(a.coverage * 100).toFixed(2).padStart(6)}%  bbox=${JSON.stringify(a.bbox)} png=${a.width}x${a.height} stable=${stable} orbit=${info.cameraOrbit} fov=${info.fov.toFixed(2)} ${((Date.now() - t0) / 1000).toFixed(1)}s`);
    } catch (e) {
      results.models[name] = { file, error: String(e && e.message || e), logs: logs.slice(-10) };
      console.log(`${name}: FAILED ${e && e.message}\n  ${logs.slice(-10).join('\n  ')}`);
    }
    await page.close();
  }
  await browser.close();
  server.close();
  const outFile = path.join(OUT, only.length ? 'coverage.partial.json' : 'coverage.json');
  fs.writeFileSync(outFile, JSON.stringify(results, null, 2) + '\n');
  console.log('wrote', outFile);
})().catch(e => { console.error(e); process.exit(1); });
