// Serves a folder (build-web/site) on 127.0.0.1 for scripts/run.sh --web: static files with the
// types browsers want (application/wasm lets them compile while downloading), nothing else.
'use strict';
const http = require('http');
const fs = require('fs');
const path = require('path');

const root = path.resolve(process.argv[2]);
const port = Number(process.argv[3] || 8080);
const types = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.wasm': 'application/wasm',
                '.data': 'application/octet-stream' };
const server = http.createServer((request, response) => {
  // A broken %-escape or a NUL byte is a bad request, never a reason to stop serving.
  let wanted;
  try {
    wanted = decodeURIComponent(request.url.split(/[?#]/)[0]);
  } catch (error) {
    response.writeHead(400);
    response.end('bad address');
    return;
  }
  const file = path.join(root, path.normalize(wanted === '/' ? '/index.html' : wanted));
  if (wanted.includes('\0') || !file.startsWith(root + path.sep)) { response.writeHead(403); response.end(); return; }
  fs.readFile(file, (error, data) => {
    if (error) { response.writeHead(404); response.end('not found'); return; }
    response.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    response.end(data);
  });
});
server.on('error', (error) => {
  console.error(`serve: cannot serve on 127.0.0.1:${port} (${error.code || error.message}); give another port: scripts/run.sh --web PORT`);
  process.exit(2);
});
server.listen(port, '127.0.0.1', () => {
  console.log(`FrictionLab's page: http://127.0.0.1:${port}/  (Ctrl+C stops serving)`);
});
