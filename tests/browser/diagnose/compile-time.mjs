// Diagnosis: what SwiftShader charges to compile a shader module, without the app. In a
// bare WebGL2 page, compiles and links each NAME's GLSL (DIR/NAME.vert, DIR/NAME.frag:
// `cargo run -p marbling-gpu --example webgl2_glsl -- DIR`) and draws one triangle with
// zeroed uniform buffers (SwiftShader builds its routine at the first draw), REPS times
// with the names interleaved (machine drift hits all alike), a fresh comment each time so
// no cache answers; prints each name's median and every time, in ms:
//
//   node compile-time.mjs DIR NAME… [REPS=5 in the environment]
import fs from 'node:fs';
import path from 'node:path';
import { launch } from '../harness.mjs';

const [dir, ...names] = process.argv.slice(2);
const reps = Number(process.env.REPS ?? 5);
const { browser } = await launch('webgl2');
const page = await browser.newPage();
await page.goto('about:blank');
const times = Object.fromEntries(names.map((n) => [n, []]));
for (let rep = 0; rep < reps; rep++) {
  for (const name of names) {
    const vs = fs.readFileSync(path.join(dir, `${name}.vert`), 'utf8');
    const fsrc = fs.readFileSync(path.join(dir, `${name}.frag`), 'utf8');
    const [status, ms] = await page.evaluate(([vs, fsrc, salt]) => {
      const canvas = document.createElement('canvas');
      canvas.width = 64;
      canvas.height = 64;
      const gl = canvas.getContext('webgl2');
      const salted = (s) => s.replace('#version 300 es', `#version 300 es\n// ${salt}`);
      const t0 = performance.now();
      const shader = (type, src) => {
        const s = gl.createShader(type);
        gl.shaderSource(s, salted(src));
        gl.compileShader(s);
        return s;
      };
      const f = shader(gl.FRAGMENT_SHADER, fsrc);
      const p = gl.createProgram();
      gl.attachShader(p, shader(gl.VERTEX_SHADER, vs));
      gl.attachShader(p, f);
      gl.linkProgram(p);
      if (!gl.getProgramParameter(p, gl.LINK_STATUS)) return [`link failed: ${gl.getProgramInfoLog(p)} ${gl.getShaderInfoLog(f)}`, 0];
      gl.useProgram(p);
      for (let b = 0; b < gl.getProgramParameter(p, gl.ACTIVE_UNIFORM_BLOCKS); b++) {
        const buffer = gl.createBuffer();
        gl.bindBuffer(gl.UNIFORM_BUFFER, buffer);
        gl.bufferData(gl.UNIFORM_BUFFER, gl.getActiveUniformBlockParameter(p, b, gl.UNIFORM_BLOCK_DATA_SIZE), gl.STATIC_DRAW);
        gl.uniformBlockBinding(p, b, b);
        gl.bindBufferBase(gl.UNIFORM_BUFFER, b, buffer);
      }
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
      const ms = performance.now() - t0;
      const error = gl.getError();
      gl.getExtension('WEBGL_lose_context')?.loseContext();
      return [error === 0 ? 'ok' : `GL error ${error}`, ms];
    }, [vs, fsrc, `${Date.now()} ${rep}`]);
    if (status !== 'ok') throw new Error(`${name}: ${status}`);
    times[name].push(ms);
  }
}
const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];
for (const name of names) {
  console.log(`${name.padEnd(16)} median ${median(times[name]).toFixed(0).padStart(5)} ms   all ${times[name].map((t) => t.toFixed(0)).join(' ')}`);
}
await browser.close();
