// The command line in WebAssembly (build-web/frictionlab-cli.js under node): every built-in
// lesson's check passes, and `run --csv` gives the native program's record. Run by
// scripts/web_test.sh, which names the native build when there is one (FRICTIONLAB_NATIVE_BUILD).
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const { spawnSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const build = process.env.FRICTIONLAB_WEB_BUILD;
const native = process.env.FRICTIONLAB_NATIVE_BUILD;
const cli = path.join(build, 'frictionlab-cli.js');
const web = (...args) => spawnSync('node', [cli, ...args], { encoding: 'utf8', maxBuffer: 64 << 20 });
const lessons = web('list', '--tsv').stdout.trim().split('\n').map((line) => line.split('\t')[0]);

test('list names every built-in lesson', () => {
  assert.ok(lessons.length >= 15, 'list gave ' + lessons.join(', '));
  assert.ok(lessons.includes('push') && lessons.includes('wedge'));
});

test('every built-in lesson meets its expectations under node', () => {
  const result = web('check');
  assert.equal(result.status, 0, result.stdout.slice(-3000) + result.stderr);
  assert.match(result.stdout, /every lesson meets its expectations/);
});

test('bad input says what and where, with exit code 2; render is the desktop\'s', () => {
  const unknown = web('run', 'push', '--set', 'mass=99');
  assert.equal(unknown.status, 2);
  assert.match(unknown.stderr, /mass/);
  const render = web('render', 'push');
  assert.equal(render.status, 2);
  assert.match(render.stderr, /render and bench are the desktop program's/);
});

// Box2D works in float and the scripts in double: the same lesson gives the same record to
// the last digit, but for wedge. Its surface turns as θ0·sin(ω·t), and the sine of glibc (the
// native program) and of musl (emscripten's libc) differ in the last bit for some t; wedge's
// block sticks and slips on that surface, and a last-bit difference in the angle moves a
// stick-slip switch by a step, after which the two records differ at the 1e-4 level (both
// still meet every expectation). That is libm's, not the port's; only one sine shared by both
// builds would remove it. The test holds wedge to the same rows for its first 100 (the first
// difference is at row 139 at the defaults), and every other lesson to every row.
test('run --csv gives the native program\'s record', { skip: !native && 'no native build given' }, () => {
  const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'frictionlab-csv-'));
  try {
    for (const lesson of lessons) {
      const webCsv = path.join(folder, lesson + '_web.csv'), nativeCsv = path.join(folder, lesson + '_native.csv');
      assert.equal(web('run', lesson, '--csv', webCsv).status, 0, lesson);
      // Written with the user's umask, as the native program writes it (emscripten's own is 0777).
      assert.equal(fs.statSync(webCsv).mode & 0o777, 0o666 & ~process.umask(), lesson + ': the CSV file\'s permissions');
      assert.equal(spawnSync(path.join(native, 'app', 'frictionlab'), ['run', lesson, '--csv', nativeCsv]).status, 0, lesson);
      const a = fs.readFileSync(webCsv, 'utf8').split('\n'), b = fs.readFileSync(nativeCsv, 'utf8').split('\n');
      assert.equal(a.length, b.length, lesson + ': a different number of rows');
      const first = a.findIndex((row, i) => row !== b[i]);
      if (lesson !== 'wedge') {
        assert.equal(first, -1, `${lesson}: row ${first + 1} differs:\n  web    ${a[first]}\n  native ${b[first]}`);
      } else {
        assert.ok(first === -1 || first > 100, `wedge differs from row ${first + 1}`);
      }
    }
  } finally {
    fs.rmSync(folder, { recursive: true, force: true });
  }
});

// A page's own link puts other parts before the setup (#lesson=...&setup=..., &projector=1): the
// command line finds the setup wherever it stands in the fragment, as the page does.
test('link reads a setup wherever it stands in the link\'s fragment', () => {
  const setup = encodeURIComponent('# FrictionLab setup\nlesson incline\nset mass = 3\n');
  for (const link of ['https://school.example/fl/#setup=' + setup, 'https://school.example/fl/#lesson=push&setup=' + setup,
                      'frictionlab.html#projector=1&at=2&setup=' + setup + '&lesson=push']) {
    const back = web('link', link);
    assert.equal(back.status, 0, link + ': ' + back.stderr);
    assert.match(back.stdout, /^lesson incline$/m, link);
    assert.match(back.stdout, /^set mass = 3$/m, link);
  }
});
