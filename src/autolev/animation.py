"""A stick figure of a model moving over a run.

The figure is the model's points located from the Newtonian origin NO, drawn in the
Newtonian frame's basis and joined wherever the model gave one point's position from
another (`P_O_P> = ...`); mass centers are drawn larger.  It is written as a
self-contained HTML page (a 3-D view to rotate with the mouse and a time slider, no
network needed) and, with matplotlib, as a GIF (or an MP4 where ffmpeg is installed);
matplotlib, optional, is imported only where the movie is drawn.
"""
from __future__ import annotations

import html
import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .runtime.errors import AutolevModelError
from .runtime.numerics.inputs import Inputs, display_name

# frames drawn at most: more rows are sampled evenly (the page and the GIF stay small)
MAX_FRAMES = 400


@dataclass
class Motion:
    """Where every point of the figure is at each drawn time."""

    frame: str                       # the Newtonian frame's name
    names: list[str]                 # the points
    edges: list[tuple[int, int]]     # pairs of point indices
    centers: list[int]               # points that are mass centers
    times: np.ndarray                # (frames,)
    xyz: np.ndarray                  # (frames, points, 3), in the frame's basis

    @property
    def planar(self) -> bool:
        """All points stay in the plane z = 0 of the frame."""
        scale = max(1.0, float(np.abs(self.xyz).max()))
        return bool(np.abs(self.xyz[:, :, 2]).max() <= 1e-9 * scale)


def figure_points(model):
    """(points, edges, centers, position expressions) of the model's figure: every point
    whose position from NO is defined, as three measure numbers in N each."""
    newtonian = model.newtonian_frame
    if newtonian is None:
        raise AutolevModelError("no NEWTONIAN frame: there is nothing to draw the motion in")
    origin = newtonian.origin
    centers = {id(b.masscenter) for b in model.bodies_list if b.masscenter is not None}
    points, exprs = [], []
    for point in [origin] + [p for p in model.points_by_name.values() if p is not origin]:
        try:
            position = point.pos_from(origin).to_matrix(newtonian)
        except AutolevModelError:
            continue                 # not located from NO: not part of the figure
        points.append(point)
        exprs.extend(position)
    if len(points) < 2:
        raise AutolevModelError(f"no point has a position from {origin.name}: there is "
                                "no figure to draw (define P_NO_P> for the points)")
    index = {id(p): k for k, p in enumerate(points)}
    edges = sorted({tuple(sorted((index[id(p)], index[id(q)])))
                    for p in points for q in p.linked_points() if id(q) in index})
    return points, edges, [k for k, p in enumerate(points) if id(p) in centers], exprs


def motion(model, result, max_frames: int = MAX_FRAMES) -> Motion:
    """The figure's motion over a run's rows (at most max_frames of them, evenly)."""
    if result.system is None or not len(result.t):
        raise AutolevModelError("the run has no rows to animate")
    if len(result.t) != len(result.states):
        raise AutolevModelError("the run kept only its last row (keep_rows=False)")
    points, edges, centers, exprs = figure_points(model)
    evaluate = result.system.evaluator(exprs, "autolev_figure",
                                       _geometry_values(model, result.system, exprs))
    rows = np.unique(np.linspace(0, len(result.t) - 1, min(max_frames, len(result.t)))
                     .round().astype(int))
    xyz = np.array([evaluate(result.t[k], result.states[k]) for k in rows])
    xyz = xyz.reshape(len(rows), len(points), 3)
    if not np.all(np.isfinite(xyz)):
        raise AutolevModelError("the figure's positions are not finite along the run")
    return Motion(model.newtonian_frame.name, [p.name for p in points], list(edges),
                  centers, np.asarray(result.t)[rows], xyz)


def _geometry_values(model, system, exprs) -> dict:
    """Values of the constants only the figure uses (a link length the equations do not
    need), from the model's INPUT statements."""
    lacking = system.lacking(exprs)
    if not lacking:
        return {}
    inputs = Inputs(model, lacking, ())
    missing = inputs.missing(lacking)
    if missing:
        raise AutolevModelError("the figure needs values the run does not: "
                                + ", ".join(display_name(k) for k in missing)
                                + " (give them INPUT values in the model)")
    return {k: inputs.internal(k) for k in lacking}


# -- the HTML page ---------------------------------------------------------------------------
def _script_json(value) -> str:
    """JSON that can sit inside a <script> element whatever names it carries."""
    text = json.dumps(value, separators=(",", ":"))
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>@TITLE@</title>
<style>
 body { margin: 0; font: 14px sans-serif; background: #ffffff; color: #222222; }
 #bar { padding: 6px 10px; display: flex; gap: 10px; align-items: center; }
 #time { width: 60%; } canvas { display: block; cursor: grab; }
</style></head><body>
<div id="bar"><button id="play">pause</button><input id="time" type="range" min="0"
 value="0"><span id="label"></span></div>
<canvas id="view"></canvas>
<script id="motion" type="application/json">@DATA@</script>
<script>
"use strict";
const M = JSON.parse(document.getElementById("motion").textContent);
const canvas = document.getElementById("view"), ctx = canvas.getContext("2d");
const slider = document.getElementById("time"), label = document.getElementById("label");
const button = document.getElementById("play");
slider.max = M.times.length - 1;
let frame = 0, playing = true, yaw = M.planar ? 0 : 0.6, pitch = M.planar ? 0 : 0.4;
let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
for (const f of M.xyz) for (const p of f) for (let i = 0; i < 3; i++) {
  lo[i] = Math.min(lo[i], p[i]); hi[i] = Math.max(hi[i], p[i]); }
const mid = lo.map((v, i) => (v + hi[i]) / 2);
const span = Math.max(1e-12, ...hi.map((v, i) => v - lo[i]));
function project(p) {
  const x = p[0] - mid[0], y = p[1] - mid[1], z = p[2] - mid[2];
  const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
  const x1 = cy * x + sy * z, z1 = -sy * x + cy * z;
  const y1 = cp * y - sp * z1;
  const s = 0.8 * Math.min(canvas.width, canvas.height) / span;
  return [canvas.width / 2 + s * x1, canvas.height / 2 - s * y1];
}
function axes() {
  const o = [40, canvas.height - 40], names = [M.frame + "1", M.frame + "2", M.frame + "3"];
  const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
  const unit = [[cy, -sp * -sy], [0, cp], [sy, -sp * cy]];
  ctx.strokeStyle = "#888888"; ctx.fillStyle = "#888888";
  unit.forEach((u, i) => {
    ctx.beginPath(); ctx.moveTo(o[0], o[1]);
    ctx.lineTo(o[0] + 25 * u[0], o[1] - 25 * u[1]); ctx.stroke();
    ctx.fillText(names[i] + ">", o[0] + 30 * u[0], o[1] - 30 * u[1]);
  });
}
function draw() {
  ctx.fillStyle = "#ffffff"; ctx.fillRect(0, 0, canvas.width, canvas.height);
  const pts = M.xyz[frame].map(project);
  ctx.lineWidth = 3; ctx.strokeStyle = "#1f77b4";
  for (const [a, b] of M.edges) {
    ctx.beginPath(); ctx.moveTo(...pts[a]); ctx.lineTo(...pts[b]); ctx.stroke(); }
  pts.forEach((p, k) => {
    const center = M.centers.includes(k);
    ctx.fillStyle = center ? "#d62728" : "#ff7f0e";
    ctx.beginPath(); ctx.arc(p[0], p[1], center ? 7 : 4, 0, 2 * Math.PI); ctx.fill();
    ctx.fillStyle = "#222222"; ctx.fillText(M.names[k], p[0] + 8, p[1] - 8);
  });
  ctx.lineWidth = 1; axes();
  label.textContent = "T = " + M.times[frame].toPrecision(6);
  slider.value = frame;
}
function resize() {
  canvas.width = window.innerWidth; canvas.height = window.innerHeight - 40; draw(); }
let drag = null;
canvas.onmousedown = e => { drag = [e.clientX, e.clientY, yaw, pitch]; };
window.onmouseup = () => { drag = null; };
window.onmousemove = e => { if (!drag) return;
  yaw = drag[2] + (e.clientX - drag[0]) / 150; pitch = drag[3] + (e.clientY - drag[1]) / 150;
  draw(); };
slider.oninput = () => { frame = +slider.value; draw(); };
button.onclick = () => { playing = !playing; button.textContent = playing ? "pause" : "play"; };
setInterval(() => { if (playing) { frame = (frame + 1) % M.times.length; draw(); } }, 40);
window.onresize = resize; resize();
</script></body></html>
"""


def write_html(m: Motion, path: Path, title: str) -> Path:
    data = {"frame": m.frame, "names": m.names, "edges": m.edges, "centers": m.centers,
            "times": [float(t) for t in m.times], "planar": m.planar,
            "xyz": np.round(m.xyz, 12).tolist()}
    page = PAGE.replace("@TITLE@", html.escape(title)).replace("@DATA@", _script_json(data))
    path = Path(path)
    path.write_text(page, encoding="utf-8")
    return path


# -- GIF and MP4 ------------------------------------------------------------------------------
def write_movie(m: Motion, path: Path, fps: int = 25) -> Path:
    """A GIF (Pillow, which matplotlib brings) or an MP4 (needs ffmpeg) by the suffix."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import animation as mpl_animation

    path = Path(path)
    if path.suffix.lower() == ".mp4":
        if not mpl_animation.FFMpegWriter.isAvailable():
            raise AutolevModelError("an MP4 needs ffmpeg, which is not installed; write a "
                                    "GIF or the HTML page instead")
        writer = mpl_animation.FFMpegWriter(fps=fps)
    else:
        writer = mpl_animation.PillowWriter(fps=fps)
    planar = m.planar
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(111) if planar else fig.add_subplot(111, projection="3d")
    lo, hi = m.xyz.min(axis=(0, 1)), m.xyz.max(axis=(0, 1))
    mid, half = (lo + hi) / 2, max(1e-12, float((hi - lo).max())) * 0.55
    for k, set_lim in enumerate((ax.set_xlim, ax.set_ylim) if planar else
                                (ax.set_xlim, ax.set_ylim, ax.set_zlim)):
        set_lim(mid[k] - half, mid[k] + half)
    labels = [f"{m.frame}{k}>" for k in (1, 2, 3)]
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    if planar:
        ax.set_aspect("equal")
    else:
        ax.set_zlabel(labels[2])
    dims = 2 if planar else 3
    lines = [ax.plot(*([[0, 0]] * dims), color="#1f77b4", lw=3)[0] for _ in m.edges]
    dots = ax.plot(*([[]] * dims), "o", color="#ff7f0e")[0]
    title = ax.set_title("")

    def show(k):
        p = m.xyz[k]
        for line, (a, b) in zip(lines, m.edges):
            line.set_data([p[a, 0], p[b, 0]], [p[a, 1], p[b, 1]])
            if not planar:
                line.set_3d_properties([p[a, 2], p[b, 2]])
        dots.set_data(p[:, 0], p[:, 1])
        if not planar:
            dots.set_3d_properties(p[:, 2])
        title.set_text(f"T = {m.times[k]:.6g}")
        return lines + [dots, title]
    movie = mpl_animation.FuncAnimation(fig, show, frames=len(m.times), blit=False)
    movie.save(str(path), writer=writer)
    plt.close(fig)
    return path
