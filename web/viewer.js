// The room, live: the shared canvas, every turtle, every drawing and the
// scoreboard, from the viewer's WebSocket (/room). The first message, on
// every (re)connect, is a snapshot; then each brings only what changed.
// The page only reads: it sends nothing. A quiet room still says it is
// there every 2 s; a page that hears nothing for STALE_MS says it is stale.
// A page the viewer refuses (it shows as many pages as it may) says why and
// tries again later and later, up to RETRY_MOST_MS.
'use strict';

const RETRY_FIRST_MS = 500;
const RETRY_MOST_MS = 8000;
const STALE_MS = 6000;
const REFUSED = 1013;           // the viewer's close code for "try again later"
const PEN_WIDTH = 3;            // px: turtlesim's default pen

const canvas = document.getElementById('canvas').getContext('2d');
const overlay = document.getElementById('turtles').getContext('2d');
let turtles = {};               // name: [x, y, theta]
let loading = null;             // strokes that came while the snapshot's picture loads
let retryMs = RETRY_FIRST_MS;
let heard = null;               // when the viewer last said anything (null: not connected)

function say(text, down) {
  const status = document.getElementById('status');
  status.textContent = text;
  status.className = down ? 'down' : '';
}

function connect() {
  const scheme = location.protocol === 'https:' ? 'wss://' : 'ws://';
  const socket = new WebSocket(scheme + location.host + '/room');
  socket.onopen = () => say('connected, waiting for the room…');
  socket.onmessage = (event) => {
    if (heard === null) { retryMs = RETRY_FIRST_MS; }
    heard = Date.now();
    say('live');
    const message = JSON.parse(event.data);
    if (message.kind !== 'alive') show(message);
  };
  socket.onclose = (event) => {
    heard = null;
    const why = event.reason ? ` (${event.reason})` : '';
    const refused = event.code === REFUSED ? 'refused' : 'reconnecting';
    say(`${refused}${why}: trying again in ${retryMs / 1000} s…`, true);
    setTimeout(connect, retryMs);
    retryMs = Math.min(2 * retryMs, RETRY_MOST_MS);
  };
}

function markStale() {
  const quiet = heard === null ? 0 : Date.now() - heard;
  if (quiet > STALE_MS) say(`stale: nothing from the viewer for ${Math.round(quiet / 1000)} s`, true);
}

function show(message) {
  if (message.kind === 'snapshot') {
    turtles = {};
    loading = [];
    const picture = new Image();
    picture.onload = () => {
      canvas.drawImage(picture, 0, 0);
      loading.forEach(drawStrokes);
      loading = null;
    };
    picture.src = message.canvas;
  } else if (loading !== null) {
    loading.push(message.strokes);
  } else {
    drawStrokes(message.strokes);
  }
  Object.assign(turtles, message.turtles);
  (message.gone || []).forEach((name) => delete turtles[name]);
  drawTurtles();
  showRoom(message.room);
  document.body.dataset.updates = Number(document.body.dataset.updates || 0) + 1;
}

function drawStrokes(byPen) {
  canvas.lineCap = 'square';     // as turtlesim's pen
  for (const [pen, points] of Object.entries(byPen || {})) {
    const [colour, width] = pen.split('/');
    canvas.strokeStyle = colour;
    canvas.lineWidth = Number(width) || PEN_WIDTH;
    canvas.beginPath();
    for (let i = 0; i + 3 < points.length; i += 4) {
      canvas.moveTo(points[i], points[i + 1]);
      canvas.lineTo(points[i + 2], points[i + 3]);
    }
    canvas.stroke();
  }
}

function drawTurtles() {
  overlay.clearRect(0, 0, 500, 500);
  overlay.font = '12px sans-serif';
  const names = Object.keys(turtles).sort();
  for (const name of names) {
    const [x, y, theta] = turtles[name];
    overlay.save();
    overlay.translate(x, y);
    overlay.rotate(-theta);
    overlay.fillStyle = '#2e7d32';
    overlay.beginPath();
    overlay.moveTo(9, 0);
    overlay.lineTo(-6, 6);
    overlay.lineTo(-6, -6);
    overlay.closePath();
    overlay.fill();
    overlay.restore();
    overlay.fillStyle = '#ffffff';
    overlay.fillText(name, x + 8, y - 8);
  }
  const list = document.getElementById('turtle-names');
  list.replaceChildren(...names.map((name) => {
    const item = document.createElement('li');
    item.textContent = name;
    return item;
  }));
}

function cell(row, content) {
  const td = row.insertCell();
  if (content instanceof Node) td.appendChild(content); else td.textContent = content;
}

function showRoom(room) {
  if (!room) return;
  if (room.drawings) {
    const body = document.querySelector('#drawings tbody');
    body.replaceChildren();
    for (const student of Object.keys(room.drawings).sort()) {
      const d = room.drawings[student];
      const row = body.insertRow();
      const bar = document.createElement('progress');
      bar.max = 1;
      bar.value = d.progress;
      cell(row, student);
      cell(row, d.text);
      cell(row, bar);
      cell(row, d.eta === null ? '' : `${d.eta.toFixed(0)} s`);
      cell(row, d.ended || (d.paused ? 'paused' : ''));
    }
  }
  if (room.scoreboard !== undefined) {
    document.getElementById('scoreboard').textContent = room.scoreboard;
    document.getElementById('scoreboard-section').hidden = !room.scoreboard;
  }
}

connect();
setInterval(markStale, 1000);
