// FrictionLab's web page in Debian's Chromium, headless, driven as a teacher and a student use
// it: the site over http from 127.0.0.1 and the single file from file://. Run by
// scripts/web_test.sh (node --test); every picture it takes is left in $FRICTIONLAB_PAGE_SHOTS.
//
// Positions come from the classroom itself (the frictionlab_control and
// frictionlab_body_on_screen hooks, in the canvas's pixels), so a layout change moves the clicks
// with it instead of breaking them.
'use strict';
const { test, before, after } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('fs');
const path = require('path');
const http = require('http');
const puppeteer = require('puppeteer-core');

const build = process.env.FRICTIONLAB_WEB_BUILD;
const shots = process.env.FRICTIONLAB_PAGE_SHOTS;
const chromium = process.env.FRICTIONLAB_CHROMIUM || '/usr/bin/chromium';
assert.ok(build && shots, 'FRICTIONLAB_WEB_BUILD and FRICTIONLAB_PAGE_SHOTS must be set (scripts/web_test.sh sets them)');

let server, site, browser;
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.data': 'application/octet-stream' };

before(async () => {
  // The site as a school's web server would give it: static files, nothing else.
  server = http.createServer((request, response) => {
    const wanted = decodeURIComponent(request.url.split(/[?#]/)[0]);
    const file = path.join(build, 'site', wanted === '/' ? 'index.html' : path.normalize(wanted));
    if (!file.startsWith(path.join(build, 'site'))) { response.writeHead(403); response.end(); return; }
    fs.readFile(file, (error, data) => {
      if (error) { response.writeHead(404); response.end(); return; }
      response.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
      response.end(data);
    });
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  site = 'http://127.0.0.1:' + server.address().port + '/';
  // WebGL 2 through SwiftShader on the CPU; no connections anywhere but the page's own server.
  browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    userDataDir: fs.mkdtempSync(path.join(shots, 'profile-')),
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic', '--disable-features=Translate'],
  });
});

after(async () => {
  if (browser) await browser.close();
  if (server) server.close();
});

// A page at 1920×1080 whose classroom has drawn its first frame. `fragment`: a link's.
async function openPage(address, options = {}) {
  const page = await browser.newPage();
  await page.setViewport({ width: options.width || 1920, height: options.height || 1080, deviceScaleFactor: options.scale || 1,
                           hasTouch: !!options.touch });
  const problems = [];
  page.on('pageerror', (error) => problems.push(error.message));
  page.problems = problems;
  const started = Date.now();
  await page.goto(address);
  await page.waitForFunction(() => typeof Module !== 'undefined' && Module.calledRun && Module._frictionlab_frames_drawn() > 0,
                             { timeout: 60000 });
  page.firstFrameMs = Date.now() - started;
  await settled(page);
  return page;
}

const call = (page, name, ...args) => page.evaluate((name, args) =>
  Module.ccall(name, typeof args[0] === 'string' || args.length === 0 ? 'string' : 'number',
               args.map((a) => typeof a), args), name, args);
const number = (page, name) => page.evaluate((name) => Module['_' + name](), name);

// Waits until the page's loop has gone to sleep: nothing moving, no input being settled.
async function settled(page) {
  let last = -1;
  for (let i = 0; i < 100; ++i) {
    const drawn = await number(page, 'frictionlab_frames_drawn');
    if (drawn === last) return drawn;
    last = drawn;
    await new Promise((resolve) => setTimeout(resolve, 150));
  }
  throw new Error('the page never stopped drawing');
}

// A control's middle in the page's CSS pixels.
async function where(page, control) {
  const rect = await call(page, 'frictionlab_control', control);
  assert.ok(rect, 'the classroom drew no control named ' + control);
  const [x0, y0, x1, y1] = rect.split(' ').map(Number);
  return page.evaluate((x, y) => {
    const box = document.getElementById('canvas').getBoundingClientRect();
    return { x: box.left + x / devicePixelRatio, y: box.top + y / devicePixelRatio };
  }, (x0 + x1) / 2, (y0 + y1) / 2);
}
async function bodyAt(page, body) {
  const at = await call(page, 'frictionlab_body_on_screen', body);
  assert.ok(at, 'no body named ' + body);
  const [x, y] = at.split(' ').map(Number);
  return page.evaluate((x, y) => {
    const box = document.getElementById('canvas').getBoundingClientRect();
    return { x: box.left + x / devicePixelRatio, y: box.top + y / devicePixelRatio };
  }, x, y);
}
// A hand's pace: each event gets a frame of its own, as ImGui 1.86 reads the mouse once a frame.
const frame = () => new Promise((resolve) => setTimeout(resolve, 50));
// `settle`: wait for the page to stop drawing after it (not while a run plays).
async function click(page, control, settle = true) {
  const at = await where(page, control);
  await page.mouse.move(at.x, at.y);
  await frame();
  await page.mouse.down();
  await frame();
  await page.mouse.up();
  if (settle) await settled(page); else await frame();
}
async function drag(page, from, to, steps = 10) {
  await page.mouse.move(from.x, from.y);
  await frame();
  await page.mouse.down();
  await frame();
  for (let i = 1; i <= steps; ++i) {
    await page.mouse.move(from.x + (to.x - from.x) * i / steps, from.y + (to.y - from.y) * i / steps);
    await frame();
  }
  await page.mouse.up();
  await settled(page);
}
// The help panel a first visit opens with covers the lesson's controls: F1 closes it, as a
// teacher would.
async function closeHelp(page) {
  await page.keyboard.press('F1');
  await settled(page);
}
async function shoot(page, name) {
  const file = path.join(shots, name + '.png');
  await page.screenshot({ path: file });
  return file;
}

test('the site opens on the first lesson and draws it over WebGL 2', async () => {
  const page = await openPage(site);
  console.log(`# first frame ${page.firstFrameMs} ms after navigation`);
  // Asking a canvas for the context it already has gives it back; any other kind gives null.
  assert.equal(await page.evaluate(() => !!document.getElementById('canvas').getContext('webgl2')), true,
               'the canvas holds no WebGL 2 context');
  assert.match(await page.title(), /spring_pull|spring/i);
  assert.deepEqual(page.problems, []);
  await shoot(page, 'site_first_frame');
  await page.close();
});

test('a paused page with no input draws no frames', async () => {
  const page = await openPage(site);
  const before = await settled(page);
  await new Promise((resolve) => setTimeout(resolve, 2000));
  assert.equal(await number(page, 'frictionlab_frames_drawn'), before, 'frames were drawn while nothing could change');
  // Input wakes it, and it sleeps again.
  await page.mouse.move(300, 300);
  await page.mouse.move(320, 310);
  await new Promise((resolve) => setTimeout(resolve, 300));
  assert.ok(await number(page, 'frictionlab_frames_drawn') > before, 'moving the mouse drew nothing');
  await settled(page);
  await page.close();
});

test('push with predictions: a slider dragged, a value typed, a prediction, play, reveal', async () => {
  const page = await openPage(site + '#lesson=push');
  assert.equal(await call(page, 'frictionlab_lesson_path'), '/lessons/push.lua');
  await closeHelp(page);
  // Drag the mass slider past its right end, letting go off the page: 10 kg.
  const slider = await where(page, 'mass slider');
  await drag(page, slider, { x: slider.x + 1500, y: slider.y });
  assert.equal(await call(page, 'frictionlab_parameter', 'mass'), '10');
  // Type an exact value: push_rate 5 N/s.
  await click(page, 'push_rate value');
  await page.keyboard.down('Control');
  await page.keyboard.press('a');
  await page.keyboard.up('Control');
  await page.keyboard.type('5');
  await page.keyboard.press('Enter');
  await settled(page);
  assert.equal(await call(page, 'frictionlab_parameter', 'push_rate'), '5');
  // The class predicts the breakaway push before Play; the theory stays hidden until revealed.
  assert.equal(await number(page, 'frictionlab_theory_hidden'), 1);
  await click(page, 'prediction breakaway push');
  await page.keyboard.type('39');
  await page.keyboard.press('Enter');
  await settled(page);
  await click(page, 'play', false);
  assert.equal(await number(page, 'frictionlab_playing'), 1);
  await page.waitForFunction(() => Module._frictionlab_time() > 1.0, { timeout: 60000 });
  await click(page, 'play');  // pause
  assert.equal(await number(page, 'frictionlab_playing'), 0);
  await click(page, 'reveal');
  assert.equal(await number(page, 'frictionlab_theory_hidden'), 0);
  await shoot(page, 'push_revealed');
  assert.deepEqual(page.problems, []);
  await page.close();
});

test('a student edits push into a mistake (message and line shown), back, and finds the copy after a reload', async () => {
  const page = await openPage(site + '#lesson=push');
  await closeHelp(page);
  await page.click('#edit');
  await page.waitForSelector('#editor.open');
  const original = await page.$eval('#source', (source) => source.value);
  assert.match(original, /parameter \{ "mass"/);
  // Line 26 holds the mass parameter: break it.
  const broken = original.split('\n');
  const line = broken.findIndex((text) => text.includes('parameter { "mass"')) + 1;
  broken[line - 1] = 'local mass = parameter { "mass", 1.0, min = 0.1, max = 10 unit = "kg" }';
  await page.$eval('#source', (source, text) => { source.value = text; }, broken.join('\n'));
  await page.click('#apply');
  await page.waitForSelector('#mistake.shown');
  const mistake = await page.$eval('#mistake', (element) => element.textContent);
  assert.match(mistake, new RegExp('my_push\\.lua:' + line + ':'), 'the message names the file and line: ' + mistake);
  assert.equal(await page.$eval('#lines .wrong', (element) => element.textContent), String(line));
  // The last good version keeps running: still push, at its values.
  assert.equal(await call(page, 'frictionlab_parameter', 'mass'), '1');
  await shoot(page, 'editor_mistake');
  // Mended, with a new default mass, it runs.
  const mended = original.replace('parameter { "mass", 1.0,', 'parameter { "mass", 2.5,');
  await page.$eval('#source', (source, text) => { source.value = text; }, mended);
  await page.keyboard.down('Control');
  await page.focus('#source');
  await page.keyboard.press('Enter');
  await page.keyboard.up('Control');
  await page.waitForFunction(() => !document.querySelector('#mistake.shown'));
  await settled(page);
  assert.match(await call(page, 'frictionlab_lesson_path'), /my_push\.lua$/);
  assert.equal(await call(page, 'frictionlab_parameter', 'mass'), '2.5');
  // Space typed in the editor is the editor's, not the classroom's Play.
  await page.focus('#source');
  await page.keyboard.press('Space');
  await new Promise((resolve) => setTimeout(resolve, 300));
  assert.equal(await number(page, 'frictionlab_playing'), 0);
  // Kept in the browser: after a reload the student's copy is still there, and opens.
  await page.waitForFunction(() => new Promise((resolve) => FS.syncfs(false, () => resolve(true))));
  await page.reload();
  await page.waitForFunction(() => typeof Module !== 'undefined' && Module.calledRun && Module._frictionlab_frames_drawn() > 0);
  const kept = '/home/web_user/.local/share/frictionlab/lessons/my_push.lua';
  assert.equal(await page.evaluate((file) => FS.analyzePath(file).exists, kept), true, 'the student\'s lesson is gone after a reload');
  assert.equal(await call(page, 'frictionlab_open', kept), '');
  assert.equal(await call(page, 'frictionlab_parameter', 'mass'), '2.5');
  assert.deepEqual(page.problems, []);
  await page.close();
});

test('a setup link opens a mystery, and a finger pulls the block through the force gauge', async () => {
  const setup = '# FrictionLab setup\nlesson push\nmystery wood/wood seed 42\nset push_rate = 0.2\npredictions off\n';
  const page = await openPage(site + '#setup=' + encodeURIComponent(setup), { touch: true });
  await closeHelp(page);
  assert.match(await call(page, 'frictionlab_lesson_path'), /push\.lua$/);
  assert.equal(await call(page, 'frictionlab_mystery_pair'), 'wood/wood');
  assert.equal(await call(page, 'frictionlab_parameter', 'push_rate'), '0.2');
  // A finger on the block, dragged to the right while the lesson plays.
  const block = await bodyAt(page, 'block');
  await page.touchscreen.touchStart(block.x, block.y);
  await frame();
  await page.keyboard.press('Space');  // play
  for (let i = 1; i <= 30; ++i) {
    await page.touchscreen.touchMove(block.x + 12 * i, block.y);
    await frame();
  }
  await shoot(page, 'gauge_touch');
  await page.touchscreen.touchEnd();
  await page.keyboard.press('Space');  // pause
  await settled(page);
  const figures = await call(page, 'frictionlab_gauge_figures');
  assert.match(figures, /peak \d/, 'the gauge read nothing: ' + figures);
  assert.deepEqual(page.problems, []);
  await page.close();
});

test('the page in one file opens from file:// with no server', async () => {
  const single = path.join(build, 'frictionlab.html');
  const bytes = fs.statSync(single).size;
  console.log(`# frictionlab.html is ${(bytes / 1e6).toFixed(2)} MB`);
  const page = await openPage('file://' + single + '#lesson=incline');
  console.log(`# first frame from file:// ${page.firstFrameMs} ms after navigation`);
  assert.match(await call(page, 'frictionlab_lesson_path'), /incline\.lua$/);
  await closeHelp(page);
  await shoot(page, 'single_file_incline');
  assert.deepEqual(page.problems, []);
  await page.close();
});
