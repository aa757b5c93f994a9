// Times lessons' physics in Debian's Chromium, in the engine the page runs in: the command line
// built for a page (build-web/bench/, the frictionlab-cli-browser target) is served from
// 127.0.0.1 and its `check LESSON --random N` called three times in one page. Prints a line
// per lesson: its name and the fastest call's seconds (the first call also pays for the
// engine's optimizing of new code; a class's page runs for minutes, past that).
//   node browser_bench.js BENCH_DIR LESSON:SETTINGS...
// Run by scripts/web_bench.sh, which gives the settings; puppeteer-core from NODE_PATH.
'use strict';
const fs = require('fs');
const http = require('http');
const path = require('path');
const puppeteer = require('puppeteer-core');

const [given, ...work] = process.argv.slice(2);
if (!given || work.length === 0) {
  console.error('usage: node browser_bench.js BENCH_DIR LESSON:SETTINGS...');
  process.exit(2);
}
const folder = path.resolve(given);
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm' };

(async () => {
  const server = http.createServer((request, response) => {
    const wanted = request.url.split(/[?#]/)[0];
    const file = path.join(folder, wanted === '/' ? 'index.html' : path.normalize(wanted));
    fs.readFile(file, (error, data) => {
      if (error || !file.startsWith(folder + path.sep)) { response.writeHead(404); response.end(); return; }
      response.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
      response.end(data);
    });
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const browser = await puppeteer.launch({
    executablePath: process.env.FRICTIONLAB_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run'],
  });
  try {
    const page = await browser.newPage();
    await page.goto('http://127.0.0.1:' + server.address().port + '/');
    await page.waitForFunction(() => window.frictionlabReady === true, { timeout: 120000 });
    for (const item of work) {
      const [lesson, settings] = item.split(':');
      let fastest = Infinity;
      for (let i = 0; i < 3; ++i) {
        const result = await page.evaluate((args) => frictionlabRun(args), ['check', lesson, '--random', settings]);
        // 1: a setting missed an expectation (timed all the same, as natively); 2: it could not run.
        if (result.status !== 0 && result.status !== 1) throw new Error(`check ${lesson} in the page: exit ${result.status}: ${result.last}`);
        fastest = Math.min(fastest, result.seconds);
      }
      console.log(`${lesson} ${fastest.toFixed(3)}`);
    }
  } finally {
    await browser.close();
    server.close();
  }
})().catch((error) => { console.error('browser_bench: ' + error.message); process.exit(1); });
