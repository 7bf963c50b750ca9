"""An interactive 3D view of a wrinkled tube: one self-contained HTML file.

The wall of :func:`shapes.wall.wall_surface` (outer face, rim, inner face) is written as
triangles with per-vertex normals and colours (the radial displacement u_r on the RdBu_r
map, as :func:`plots.render_pattern`) into a page with a small inline WebGL viewer: drag to
rotate, wheel (or pinch) to zoom. No script or style is fetched from anywhere, so the page
works offline, from the documentation site or from a file.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

import matplotlib as mpl
import numpy as np

from ..atomic import write_text
from ..shapes.mode_shape import ModeShape
from ..shapes.wall import Surface, wall_surface

MAX_VERTICES = 65535  # WebGL 1 indexes vertices with 16-bit integers


def mesh_arrays(surf: Surface) -> dict[str, list]:
    """The surface as triangles: ``position``, ``normal`` and ``color`` (flat, 3 per
    vertex, centred and scaled into the unit ball) and ``index`` (3 per triangle, two per
    grid cell)."""
    P = np.stack([surf.x, surf.y, surf.z], axis=-1)
    rows, cols = P.shape[:2]
    if rows * cols > MAX_VERTICES:
        raise ValueError(f"{rows * cols} vertices; at most {MAX_VERTICES} (a coarser grid)")
    normal = np.cross(np.gradient(P, axis=0), np.gradient(P, axis=1))
    normal /= np.maximum(np.linalg.norm(normal, axis=-1, keepdims=True), 1e-300)
    centre = 0.5 * (P.reshape(-1, 3).max(axis=0) + P.reshape(-1, 3).min(axis=0))
    scale = float(np.linalg.norm(P - centre, axis=-1).max()) or 1.0
    peak = float(np.abs(surf.u_r).max()) or 1.0
    color = mpl.colormaps["RdBu_r"](0.5 + 0.5 * surf.u_r / peak)[..., :3]
    k = np.arange(rows * cols).reshape(rows, cols)
    a, b, c, d = k[:-1, :-1], k[:-1, 1:], k[1:, 1:], k[1:, :-1]
    index = np.stack([a, b, c, a, c, d], axis=-1).reshape(-1)
    return {
        "position": np.round((P - centre) / scale, 3).reshape(-1).tolist(),
        "normal": np.round(normal, 2).reshape(-1).tolist(),
        "color": np.round(color, 2).reshape(-1).tolist(),
        "index": index.tolist(),
    }


def pattern_html(
    shape: ModeShape,
    *,
    amplitude: float = 0.1,
    n_theta: int | None = None,
    n_z: int | None = None,
    title: str = "",
) -> str:
    """The page: the wrinkled wall of ``shape`` (largest displacement ``amplitude`` R_i)
    in an inline WebGL viewer, with ``title`` (default: the mode and tube) above it."""
    surf = wall_surface(shape, amplitude=amplitude, n_theta=n_theta, n_z=n_z)
    data = json.dumps(mesh_arrays(surf), separators=(",", ":"))
    p = shape.params
    title = title or (
        f"mode (m, n) = ({shape.m}, {shape.n}), outer radius {p.outer_radius:g} R_i,"
        f" length {p.length:g} R_i, wrinkle amplitude {amplitude:g} R_i"
    )
    return PAGE.replace("%TITLE%", html.escape(title)).replace("%DATA%", data)


def write_pattern_html(shape: ModeShape, path: str | Path, **options) -> Path:
    """Write :func:`pattern_html` to ``path`` (parent directories created)."""
    return write_text(path, pattern_html(shape, **options))


PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>%TITLE%</title>
<style>
body{margin:0;font:13px sans-serif;background:#fff;color:#222}
#c{width:100%;height:calc(100vh - 3.2em);display:block;cursor:grab;touch-action:none}
p{margin:.3em .6em}
</style></head><body>
<p>%TITLE%. Colour: radial displacement (red outward, blue inward).
Drag to rotate, wheel to zoom.</p>
<canvas id="c"></canvas>
<script>
"use strict";
const D = %DATA%;
const cv = document.getElementById("c");
const gl = cv.getContext("webgl", {antialias: true});
if (!gl) { cv.outerHTML = "<p>This browser has no WebGL.</p>"; }
else {
const vs = `attribute vec3 p; attribute vec3 n; attribute vec3 c;
uniform mat4 M; uniform mat4 P; varying vec3 vn; varying vec3 vc;
void main(){ vn = (M * vec4(n, 0.0)).xyz; vc = c; gl_Position = P * M * vec4(p, 1.0); }`;
const fs = `precision mediump float; varying vec3 vn; varying vec3 vc;
void main(){ vec3 l = normalize(vec3(-0.4, 0.6, 1.0));
 float d = abs(dot(normalize(vn), l)); gl_FragColor = vec4(vc * (0.42 + 0.58 * d), 1.0); }`;
function shader(type, src) {
  const s = gl.createShader(type); gl.shaderSource(s, src); gl.compileShader(s); return s; }
const prog = gl.createProgram();
gl.attachShader(prog, shader(gl.VERTEX_SHADER, vs));
gl.attachShader(prog, shader(gl.FRAGMENT_SHADER, fs));
gl.linkProgram(prog); gl.useProgram(prog);
for (const [name, arr] of [["p", D.position], ["n", D.normal], ["c", D.color]]) {
  const b = gl.createBuffer(); gl.bindBuffer(gl.ARRAY_BUFFER, b);
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(arr), gl.STATIC_DRAW);
  const loc = gl.getAttribLocation(prog, name);
  gl.enableVertexAttribArray(loc); gl.vertexAttribPointer(loc, 3, gl.FLOAT, false, 0, 0);
}
const ib = gl.createBuffer(); gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ib);
gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint16Array(D.index), gl.STATIC_DRAW);
gl.enable(gl.DEPTH_TEST); gl.clearColor(1, 1, 1, 1);
let yaw = -0.9, pitch = -1.05, dist = 3.2;
function mul(a, b) { const o = new Array(16).fill(0);
  for (let i = 0; i < 4; i++) for (let j = 0; j < 4; j++) for (let k = 0; k < 4; k++)
    o[j * 4 + i] += a[k * 4 + i] * b[j * 4 + k];
  return o; }
function draw() {
  const w = cv.clientWidth, h = cv.clientHeight, r = window.devicePixelRatio || 1;
  if (cv.width !== w * r || cv.height !== h * r) { cv.width = w * r; cv.height = h * r; }
  gl.viewport(0, 0, cv.width, cv.height);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
  const Rz = [cy, sy, 0, 0, -sy, cy, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  const Rx = [1, 0, 0, 0, 0, cp, sp, 0, 0, -sp, cp, 0, 0, 0, 0, 1];
  const T = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -dist, 1];
  const M = mul(T, mul(Rx, Rz));
  const f = 1 / Math.tan(0.35), a = w / Math.max(h, 1), near = 0.1, far = 20;
  const P = [f / a, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1,
             0, 0, 2 * far * near / (near - far), 0];
  gl.uniformMatrix4fv(gl.getUniformLocation(prog, "M"), false, new Float32Array(M));
  gl.uniformMatrix4fv(gl.getUniformLocation(prog, "P"), false, new Float32Array(P));
  gl.drawElements(gl.TRIANGLES, D.index.length, gl.UNSIGNED_SHORT, 0);
}
let drag = null;
cv.addEventListener("pointerdown", e => { drag = [e.clientX, e.clientY];
  cv.setPointerCapture(e.pointerId); cv.style.cursor = "grabbing"; });
cv.addEventListener("pointerup", () => { drag = null; cv.style.cursor = "grab"; });
cv.addEventListener("pointermove", e => { if (!drag) return;
  yaw += 0.01 * (e.clientX - drag[0]); pitch += 0.01 * (e.clientY - drag[1]);
  pitch = Math.max(-3.1, Math.min(0.0, pitch)); drag = [e.clientX, e.clientY]; draw(); });
cv.addEventListener("wheel", e => { e.preventDefault();
  dist = Math.max(1.2, Math.min(10, dist * Math.exp(0.001 * e.deltaY))); draw(); },
  {passive: false});
window.addEventListener("resize", draw);
draw();
}
</script></body></html>
"""
