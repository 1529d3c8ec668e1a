// The viewer's floor and framing in headless Chromium: an animated
// GLB (an AMASS-layout motion with root translation) is loaded through the
// page's file input, and
//   - the floor grid is at the clip's lowest point: numpy's forward pass of
//     the motion over every frame (--reference, anim_reference.py) gives the
//     lowest vertex height; the page's floor must equal it (1e-5 m);
//   - from the scene: at the clip's lowest frame, its first, middle and last
//     frame and while playing, every skinned vertex projects inside the view
//     (NDC within [-1, 1]) and none is below the floor;
//   - from a screenshot (grid hidden, so only the body differs from the
//     background): the body's pixel box is inside the canvas and matches the
//     projected vertices' box (3 px);
// then a static GLB (no clip) is loaded while the first one plays: play and
// scrub are reset (not playing, time 0, controls disabled) and the floor is
// its rest pose's lowest vertex.
//
//   node viewer_framing_test.mjs --chromium /usr/bin/chromium --anim-asset walk.glb \
//        --reference walk_ref.json --static-asset body.glb --screenshot out.png
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { parseArgs } from 'node:util';

import { WEB_DIR } from './harness.mjs';

const { values: args } = parseArgs({
  options: {
    chromium: { type: 'string', default: '/usr/bin/chromium' }, 'anim-asset': { type: 'string' },
    reference: { type: 'string' }, 'static-asset': { type: 'string' }, screenshot: { type: 'string' },
  },
});
for (const key of ['anim-asset', 'reference', 'static-asset', 'screenshot']) {
  if (!args[key]) {
    console.error(`viewer_framing_test: --${key} is required`);
    process.exit(1);
  }
}
if (!fs.existsSync(args.chromium)) {
  console.error(`viewer_framing_test: ${args.chromium} not found (Debian package chromium)`);
  process.exit(1);
}
const puppeteer = (await import(pathToFileURL(path.join(WEB_DIR, 'node_modules/puppeteer-core/lib/esm/puppeteer/puppeteer-core.js')).href)).default;
const { startServer } = await import(pathToFileURL(path.join(WEB_DIR, 'viewer', 'serve.js')).href);

const nextFrames = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

/** Every vertex's world position and its projection (NDC, and pixels of the canvas), in the page. */
function projectAll(page) {
  return page.evaluate(() => {
    const v = window.smplViewer, cam = v.camera, canvas = document.querySelector('#view canvas');
    const V = cam.position.constructor;  // THREE.Vector3, without importing three here
    cam.updateMatrixWorld();
    const n = v.info().threeVertices;
    let minY = Infinity, ndc = { x0: Infinity, x1: -Infinity, y0: Infinity, y1: -Infinity, z0: Infinity, z1: -Infinity };
    for (let i = 0; i < n; i++) {
      const w = v.vertexWorld(i);
      minY = Math.min(minY, w[1]);
      const p = new V(w[0], w[1], w[2]).project(cam);
      ndc = { x0: Math.min(ndc.x0, p.x), x1: Math.max(ndc.x1, p.x), y0: Math.min(ndc.y0, p.y),
              y1: Math.max(ndc.y1, p.y), z0: Math.min(ndc.z0, p.z), z1: Math.max(ndc.z1, p.z) };
    }
    const W = canvas.clientWidth, H = canvas.clientHeight;
    const pixels = { left: (ndc.x0 + 1) / 2 * W, right: (ndc.x1 + 1) / 2 * W,
                     top: (1 - ndc.y1) / 2 * H, bottom: (1 - ndc.y0) / 2 * H };
    return { minY, ndc, pixels, width: W, height: H, framing: v.framing() };
  });
}

function assertInside(p, what) {
  const { ndc } = p;
  assert.ok(ndc.x0 > -1 && ndc.x1 < 1 && ndc.y0 > -1 && ndc.y1 < 1 && ndc.z0 > -1 && ndc.z1 < 1,
            `${what}: the body leaves the view (NDC ${JSON.stringify(ndc)})`);
  assert.ok(p.minY >= p.framing.floorY - 1e-6, `${what}: a vertex at y ${p.minY} is below the floor ${p.framing.floorY}`);
}

/** The body's pixel box in a screenshot of the canvas with the grid hidden (pixels unlike the background). */
async function screenshotBox(page, file) {
  const canvas = await page.$('#view canvas');
  await page.evaluate(() => { window.smplViewer.grid.visible = false; });
  await nextFrames(page);
  const png = await canvas.screenshot({ encoding: 'base64' });
  if (file) fs.writeFileSync(file, Buffer.from(png, 'base64'));
  await page.evaluate(() => { window.smplViewer.grid.visible = true; });
  return page.evaluate(async (data) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + data;
    await img.decode();
    const c = Object.assign(document.createElement('canvas'), { width: img.width, height: img.height });
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const px = ctx.getImageData(0, 0, img.width, img.height).data;
    const bg = [px[0], px[1], px[2]];  // a corner: background (the body is framed away from the edges)
    let left = Infinity, right = -Infinity, top = Infinity, bottom = -Infinity;
    for (let y = 0; y < img.height; y++) {
      for (let x = 0; x < img.width; x++) {
        const i = 4 * (y * img.width + x);
        if (Math.max(Math.abs(px[i] - bg[0]), Math.abs(px[i + 1] - bg[1]), Math.abs(px[i + 2] - bg[2])) <= 12) continue;
        left = Math.min(left, x); right = Math.max(right, x + 1); top = Math.min(top, y); bottom = Math.max(bottom, y + 1);
      }
    }
    return { left, right, top, bottom, width: img.width, height: img.height, background: bg };
  }, png);
}

test('viewer floor and framing in headless Chromium', async () => {
  const ref = JSON.parse(fs.readFileSync(args.reference, 'utf8'));
  const heights = ref.vertices.map((frame) => Math.min(...frame.map((v) => v[1])));
  const lowest = Math.min(...heights), lowestFrame = heights.indexOf(lowest);
  const server = await startServer(0);
  const browser = await puppeteer.launch({
    executablePath: args.chromium, headless: true,
    args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
           '--window-size=1280,800'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 800 });
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    await page.goto(`http://127.0.0.1:${server.address().port}/viewer/`, { waitUntil: 'load' });
    await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
    const input = await page.$('#file');
    await input.uploadFile(args['anim-asset']);
    const name = path.basename(args['anim-asset']);
    await page.waitForFunction((n) => document.getElementById('info-file').textContent === n, { timeout: 60000 }, name);

    // The floor: numpy's lowest vertex over every frame of the clip.
    const framing = await page.evaluate(() => window.smplViewer.framing());
    console.log(`floor y ${framing.floorY.toFixed(6)} grid y ${framing.gridY.toFixed(6)}; numpy's lowest vertex ` +
                `${lowest.toFixed(6)} m at frame ${lowestFrame} of ${heights.length} (frame 0's: ` +
                `${heights[0].toFixed(6)}); bounds ${JSON.stringify(framing.bounds)}`);
    assert.ok(framing.hasClip, 'the clip is selected');
    assert.ok(Math.abs(framing.floorY - lowest) <= 1e-5, `floor at ${framing.floorY}, numpy's lowest point ${lowest}`);
    assert.equal(framing.gridY, framing.floorY, 'the grid is drawn at the floor');

    // From the scene, at chosen frames (paused) and while playing.
    const frames = [...new Set([lowestFrame, 0, Math.floor(heights.length / 2), heights.length - 1])];
    for (const f of frames) {
      await page.evaluate((t) => window.smplViewer.setTime(t), f / ref.fps);
      await nextFrames(page);
      const p = await projectAll(page);
      console.log(`frame ${f}: lowest vertex y ${p.minY.toFixed(6)} NDC ${JSON.stringify(p.ndc, (k, v) => (typeof v === 'number' ? +v.toFixed(3) : v))}`);
      assertInside(p, `frame ${f}`);
      if (f === lowestFrame) {
        assert.ok(Math.abs(p.minY - framing.floorY) <= 1e-5, `at the lowest frame the body is ${p.minY - framing.floorY} m off the floor`);
        const shot = await screenshotBox(page, args.screenshot);
        console.log(`screenshot body box ${JSON.stringify(shot)}; projected ${JSON.stringify(p.pixels)}`);
        assert.ok(shot.left > 0 && shot.top > 0 && shot.right < shot.width && shot.bottom < shot.height,
                  'the body touches the screenshot\'s edge');
        for (const side of ['left', 'right', 'top', 'bottom'])
          assert.ok(Math.abs(shot[side] - p.pixels[side]) <= 3, `screenshot ${side} ${shot[side]} vs projected ${p.pixels[side]}`);
      }
    }
    await page.evaluate(() => window.smplViewer.setTime(0));
    await page.click('#play');
    await page.waitForFunction(() => window.smplViewer.framing().time > 0.3, { timeout: 30000 });
    const playing = await projectAll(page);
    console.log(`playing at ${playing.framing.time.toFixed(3)} s: NDC inside ${JSON.stringify(playing.ndc, (k, v) => (typeof v === 'number' ? +v.toFixed(3) : v))}`);
    assert.ok(playing.framing.playing, 'playing');
    assertInside(playing, 'while playing');

    // A file without clips, loaded while the first plays: play and scrub reset.
    await input.uploadFile(args['static-asset']);
    const staticName = path.basename(args['static-asset']);
    await page.waitForFunction((n) => document.getElementById('info-file').textContent === n, { timeout: 60000 }, staticName);
    await nextFrames(page);
    const reset = await page.evaluate(() => ({
      framing: window.smplViewer.framing(), play: document.getElementById('play').textContent,
      playDisabled: document.getElementById('play').disabled, scrub: Number(document.getElementById('scrub').value),
      scrubDisabled: document.getElementById('scrub').disabled, time: document.getElementById('time').textContent,
      clips: document.getElementById('clip').options.length,
    }));
    console.log(`after ${staticName}: ${JSON.stringify(reset)}`);
    assert.deepEqual([reset.framing.playing, reset.framing.hasClip, reset.play, reset.playDisabled, reset.scrub,
                      reset.scrubDisabled, reset.time, reset.clips],
                     [false, false, 'Play', true, 0, true, '0.000 s', 0], 'play/scrub state reset');
    const still = await projectAll(page);
    assertInside(still, staticName);
    assert.ok(Math.abs(still.minY - reset.framing.floorY) <= 1e-6, `static: floor ${reset.framing.floorY}, lowest vertex ${still.minY}`);
    assert.deepEqual(errors, [], 'page errors');
  } finally {
    await browser.close();
    server.close();
  }
});
