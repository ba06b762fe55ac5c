// Diagnosis: what SwiftShader charges for full-window passes, without the app. Serves a
// bare WebGPU page that clears a WIDTH × HEIGHT canvas and draws PASSES full-window
// triangles every frame, with SHADER `flat` (a little arithmetic), `load` (one
// textureLoad per pixel, as the canvas's present pass) or `sample` (one nearest
// textureSampleLevel), and prints the frames per second it keeps up:
//
//   node bare-page.mjs [PASSES] [flat|load|sample] [WIDTH] [HEIGHT] [extra Chromium flags…]
//
// Results: docs/BENCHMARKS.md, "Where the time went".
import http from 'node:http';
import { launch } from '../harness.mjs';

const [passes = '1', shader = 'flat', width = '1024', height = '768', ...extra] = process.argv.slice(2);
const PAGE = `<!doctype html><html><body style="margin:0;overflow:hidden">
<canvas id="c" style="width:100vw;height:100vh;display:block"></canvas>
<script type="module">
const c = document.getElementById('c'); c.width = innerWidth; c.height = innerHeight;
const device = await (await navigator.gpu.requestAdapter()).requestDevice();
const ctx = c.getContext('webgpu'); const format = navigator.gpu.getPreferredCanvasFormat();
ctx.configure({ device, format, alphaMode: 'opaque' });
const code = \`
@group(0) @binding(0) var img: texture_2d<f32>;
@group(0) @binding(1) var smp: sampler;
@vertex fn vs(@builtin(vertex_index) v: u32) -> @builtin(position) vec4f {
  return vec4f(f32(i32(v & 1u) * 4 - 1), f32(i32(v >> 1u) * 4 - 1), 0, 1);
}
@fragment fn flat(@builtin(position) p: vec4f) -> @location(0) vec4f {
  return vec4f(fract(p.x / 64.0), fract(p.y / 64.0), 0.5, 1);
}
@fragment fn load(@builtin(position) p: vec4f) -> @location(0) vec4f {
  let last = vec2<i32>(textureDimensions(img)) - vec2<i32>(1);
  return textureLoad(img, clamp(vec2<i32>(floor(p.xy)), vec2<i32>(0), last), 0);
}
@fragment fn sample(@builtin(position) p: vec4f) -> @location(0) vec4f {
  return textureSampleLevel(img, smp, p.xy / vec2f(textureDimensions(img)), 0.0);
}\`;
const module = device.createShaderModule({ code });
const entries = [
  { binding: 0, visibility: GPUShaderStage.FRAGMENT, texture: {} },
  { binding: 1, visibility: GPUShaderStage.FRAGMENT, sampler: {} },
];
const layout = device.createBindGroupLayout({ entries });
const pipeline = device.createRenderPipeline({
  layout: device.createPipelineLayout({ bindGroupLayouts: [layout] }),
  vertex: { module, entryPoint: 'vs' },
  fragment: { module, entryPoint: '${shader}', targets: [{ format }] },
});
const tex = device.createTexture({ size: [c.width, c.height], format: 'rgba8unorm',
  usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.RENDER_ATTACHMENT });
const group = device.createBindGroup({ layout, entries: [
  { binding: 0, resource: tex.createView() }, { binding: 1, resource: device.createSampler() }] });
window.frames = 0;
function frame() {
  const enc = device.createCommandEncoder();
  const pass = enc.beginRenderPass({ colorAttachments: [{ view: ctx.getCurrentTexture().createView(),
    loadOp: 'clear', storeOp: 'store', clearValue: [0.2, 0.3, 0.4, 1] }] });
  pass.setPipeline(pipeline); pass.setBindGroup(0, group);
  for (let i = 0; i < ${Number(passes)}; i++) pass.draw(3);
  pass.end(); device.queue.submit([enc.finish()]); window.frames++; requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
</script></body></html>`;

const server = http.createServer((_, res) => res.writeHead(200, { 'content-type': 'text/html' }).end(PAGE));
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const { browser, site } = await launch('webgpu', extra);
const page = await browser.newPage({ viewport: { width: Number(width), height: Number(height) } });
const errors = [];
page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
await page.goto(`http://127.0.0.1:${server.address().port}/`);
await page.waitForFunction(() => window.frames > 10, null, { timeout: 60_000 });
const f0 = await page.evaluate(() => window.frames);
await page.waitForTimeout(5000);
const fps = ((await page.evaluate(() => window.frames)) - f0) / 5;
console.log(`${passes} × ${shader} at ${width}×${height} ${extra.join(' ')}: ${fps.toFixed(1)} frames/s${errors.length ? `; errors: ${errors.join(' | ')}` : ''}`);
await browser.close();
site.server.close();
server.close();
