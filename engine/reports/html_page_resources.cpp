#include "reports/html_page_resources.h"

namespace candela::reports {

std::string_view htmlPageStyle() {
    return R"css(:root { --thumb-w: 160px; --thumb-h: 120px; }
* { box-sizing: border-box; }
body { margin: 0; font: 14px/1.4 "DejaVu Sans", system-ui, sans-serif; color: #1d232a; background: #f4f5f7; }
header { padding: 14px 20px 10px; background: #fff; border-bottom: 1px solid #d6dae0; }
h1 { font-size: 20px; margin: 0 0 6px; }
.summary p { margin: 0; color: #3c4650; }
.controls { position: sticky; top: 0; z-index: 2; display: flex; flex-wrap: wrap; align-items: center;
  gap: 8px 20px; padding: 8px 20px; background: #f4f5f7; border-bottom: 1px solid #d6dae0; }
.controls input[type=search] { width: 22em; max-width: 60vw; padding: 3px 6px; font: inherit; }
.controls .hint, #shown { color: #5b6670; }
main { padding: 12px 20px 24px; overflow-x: auto; }
table { border-collapse: collapse; width: 100%; background: #fff; border: 1px solid #d6dae0; }
th, td { padding: 6px 10px; border-bottom: 1px solid #e3e6ea; text-align: left; vertical-align: top; }
th { background: #e9ecf0; white-space: nowrap; font-weight: 600; }
th[data-key] { cursor: pointer; user-select: none; }
th[data-key]:hover, th[data-key]:focus { background: #dce1e7; outline: none; }
th[data-key]::after { content: " \2195"; color: #9aa4ae; }
th[aria-sort=ascending]::after { content: " \25B2"; color: #1d232a; }
th[aria-sort=descending]::after { content: " \25BC"; color: #1d232a; }
th.num, td.num { text-align: right; white-space: nowrap; font-variant-numeric: tabular-nums; }
td.num { font-family: "DejaVu Sans Mono", monospace; font-size: 13px; }
td.num.absent { color: #9aa4ae; }
tr.failed { background: #fdeceb; }
tr.over-threshold { background: #fff4e5; }
.status, .images, .num { width: 1%; }  /* as narrow as their content: the name column takes the rest */
td.status { white-space: nowrap; }
.badge { display: inline-block; padding: 1px 8px; border-radius: 10px; font-size: 12px; font-weight: 600; color: #fff; }
tr.failed .badge { background: #c62828; }
tr.over-threshold .badge { background: #e65100; }
tr.warning .badge { background: #f9a825; color: #1d232a; }
tr.ok .badge { background: #2e7d32; }
td.about { min-width: 14em; overflow-wrap: anywhere; }
.name { font-weight: 600; }
.error { margin: 4px 0; color: #b71c1c; white-space: pre-wrap; font-family: "DejaVu Sans Mono", monospace; font-size: 12px; }
details { margin: 4px 0 0; }
summary { cursor: pointer; color: #3c4650; }
details ul, ul.links { margin: 2px 0; padding-left: 18px; }
.warnings li { color: #8a4b00; }
.notes li { color: #3c4650; }
ul.links { list-style: none; padding-left: 0; display: flex; flex-wrap: wrap; gap: 0 12px; }
.thumbs { display: flex; gap: 8px; }
figure.thumb { margin: 0; }
figure.thumb img, .placeholder { display: block; width: var(--thumb-w); height: var(--thumb-h); border: 1px solid #c9ced6; }
figure.thumb img { object-fit: contain; background: #20242a; cursor: zoom-in; }
.placeholder { display: flex; align-items: center; justify-content: center; padding: 6px; text-align: center;
  color: #5b6670; background: #eceef1; border-style: dashed; font-size: 12px; }
figcaption { font-size: 12px; color: #3c4650; text-align: center; }
#empty { color: #5b6670; }
#lightbox { position: fixed; inset: 0; z-index: 10; display: flex; flex-direction: column; align-items: center;
  justify-content: center; gap: 8px; background: rgba(10, 12, 15, 0.88); cursor: zoom-out; }
#lightbox[hidden] { display: none; }
#lightbox img { image-rendering: pixelated; background: #20242a; }
#lightbox p { margin: 0; color: #e9ecf0; }
@media (max-width: 1100px) {
  :root { --thumb-w: 120px; --thumb-h: 90px; }
  header, .controls { padding-left: 10px; padding-right: 10px; }
  main { padding: 8px 10px 16px; }
  th, td { padding: 5px 6px; }
}
@media (max-width: 900px) {
  :root { --thumb-w: 88px; --thumb-h: 66px; }
  body { font-size: 13px; }
  td.about { min-width: 11em; }
  th.num { white-space: normal; }
  td.num { font-size: 12px; }
  .badge { padding: 1px 6px; font-size: 11px; }
  .thumbs { gap: 4px; }
  figcaption { font-size: 11px; }
}
)css";
}

std::string_view htmlPageScript() {
    return R"js((function () {
  'use strict';
  var tbody = document.getElementById('rows');
  var rows = Array.prototype.slice.call(tbody.rows);  // the default order
  var filter = document.getElementById('filter');
  var failuresOnly = document.getElementById('failures-only');
  var shown = document.getElementById('shown');
  var headers = Array.prototype.slice.call(document.querySelectorAll('th[data-key]'));
  var rank = { 'failed': 0, 'over-threshold': 1, 'warning': 2, 'ok': 3 };
  var collator = new Intl.Collator('en', { numeric: true, sensitivity: 'base' });
  var sorted = { key: null, dir: 1 };
  var texts = null;

  function sortBy(th, dir) {
    var key = th.dataset.key, column = th.cellIndex;
    var items = rows.map(function (row) {
      var v;
      if (key === 'name') v = row.dataset.name;
      else if (key === 'status') v = rank[row.dataset.status];
      else {
        var s = row.cells[column].dataset.value;
        v = s === '' ? NaN : Number(s);
      }
      return { row: row, v: v, i: Number(row.dataset.index) };
    });
    items.sort(function (a, b) {
      if (key === 'name') return dir * collator.compare(a.v, b.v) || a.i - b.i;
      var an = isNaN(a.v), bn = isNaN(b.v);
      if (an || bn) return an === bn ? a.i - b.i : (an ? 1 : -1);
      if (a.v !== b.v) return a.v < b.v ? -dir : dir;
      return a.i - b.i;
    });
    var fragment = document.createDocumentFragment();
    items.forEach(function (item) { fragment.appendChild(item.row); });
    tbody.appendChild(fragment);
    headers.forEach(function (h) { h.removeAttribute('aria-sort'); });
    th.setAttribute('aria-sort', dir > 0 ? 'ascending' : 'descending');
    sorted = { key: key, dir: dir };
  }

  function onHeader(th) { sortBy(th, sorted.key === th.dataset.key ? -sorted.dir : 1); }
  headers.forEach(function (th) {
    th.addEventListener('click', function () { onHeader(th); });
    th.addEventListener('keydown', function (e) {
      if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); onHeader(th); }
    });
  });

  function applyFilter() {
    var query = filter.value.trim().toLowerCase();
    var only = failuresOnly.checked;
    if (texts === null) texts = rows.map(function (row) { return row.cells[1].textContent.toLowerCase(); });
    var count = 0;
    rows.forEach(function (row, i) {
      var status = row.dataset.status;
      var show = (!only || status === 'failed' || status === 'over-threshold') &&
                 (query === '' || texts[i].indexOf(query) >= 0);
      row.hidden = !show;
      if (show) count++;
    });
    shown.textContent = count + ' of ' + rows.length + ' rows';
  }
  filter.addEventListener('input', applyFilter);
  filter.addEventListener('change', applyFilter);
  failuresOnly.addEventListener('change', applyFilter);

  var lightbox = document.getElementById('lightbox');
  var big = lightbox.querySelector('img');
  var caption = lightbox.querySelector('p');
  function closeLightbox() { lightbox.hidden = true; big.removeAttribute('src'); }
  big.addEventListener('load', function () {
    // Whole multiples of the image's size, so that pixels stay square and sharp.
    var fit = Math.min(window.innerWidth * 0.95 / big.naturalWidth, window.innerHeight * 0.85 / big.naturalHeight);
    var scale = fit >= 1 ? Math.floor(fit) : fit;
    big.style.width = Math.round(big.naturalWidth * scale) + 'px';
    big.style.height = Math.round(big.naturalHeight * scale) + 'px';
    caption.textContent = caption.dataset.label + ' \u2014 ' + big.naturalWidth + '\u00D7' + big.naturalHeight;
  });
  tbody.addEventListener('click', function (e) {
    var img = e.target.closest('figure.thumb img');
    if (!img) return;
    e.preventDefault();
    caption.dataset.label = img.closest('tr.row').dataset.name + ' \u2014 ' + img.alt;
    caption.textContent = caption.dataset.label;
    big.src = img.currentSrc || img.src;
    lightbox.hidden = false;
  });
  lightbox.addEventListener('click', closeLightbox);
  document.addEventListener('keydown', function (e) {
    if (e.key === 'Escape' && !lightbox.hidden) closeLightbox();
  });

  applyFilter();
  document.documentElement.setAttribute('data-ready', '1');
})();
)js";
}

}  // namespace candela::reports
