"""The motion of animation.py written out: a self-contained HTML page (a 3-D view to
rotate with the mouse and a time slider, no network needed) and, with matplotlib, a GIF
(or an MP4 where ffmpeg is installed); matplotlib, optional, is imported only where the
movie is drawn.
"""
from __future__ import annotations

import html
import io
import json
import os
from pathlib import Path

import numpy as np

from .animation import MARGIN, Motion, grid_lines
from ..engine.errors import AutolevModelError
from ..engine.outputs import temporary_beside, write_whole
from ..engine.progress import Progress

# the 3-D view the GIF is drawn in (the page starts from it too): radians about up, right
YAW, PITCH = 0.6, 0.4
# a movie's progress line: `p.gif: frame 3 of 40 (8%)`
FRAMES = "{what}: frame {position} of {end} ({percent:.0f}%)"


# -- the HTML page ---------------------------------------------------------------------------
COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]   # by kind: segment, axes 1, 2, 3
GRID_COLOURS = {False: "#ebebeb", True: "#c4c4c4"}        # a grid's minor and major lines


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
let frame = 0, playing = true, yaw = M.planar ? 0 : M.yaw, pitch = M.planar ? 0 : M.pitch;
const span = Math.max(1e-12, M.span);
let mid = M.centres[0];
// picture coordinates (right, up, toward the viewer) turned about up, then about right
function turn(v) {
  const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
  const x1 = cy * v[0] + sy * v[2], z1 = -sy * v[0] + cy * v[2];
  return [x1, cp * v[1] - sp * z1, sp * v[1] + cp * z1];
}
function project(p) {
  const [x, y] = turn([p[0] - mid[0], p[1] - mid[1], p[2] - mid[2]]);
  const s = 0.9 * Math.min(canvas.width, canvas.height) / span;
  return [canvas.width / 2 + s * x, canvas.height / 2 - s * y];
}
// N's axes in a corner; one along the line of sight is a dot (toward you) or a cross,
// named on the side away from the other two
function axes() {
  const o = [40, canvas.height - 40], turned = M.axes.map(turn);
  ctx.strokeStyle = "#888888"; ctx.fillStyle = "#888888";
  turned.forEach((u, i) => {
    const name = M.frame + (i + 1) + ">";
    if (Math.hypot(u[0], u[1]) < 0.2) {
      const w = [0, 0];
      turned.forEach((v, j) => { if (j !== i) { w[0] -= v[0]; w[1] -= v[1]; } });
      const n = Math.hypot(w[0], w[1]) || 1;
      ctx.fillText(u[2] > 0 ? "\u2299" : "\u2297", o[0] - 4, o[1] + 4);
      ctx.fillText(name, o[0] - 10 + 22 * w[0] / n, o[1] + 4 - 22 * w[1] / n);
      return;
    }
    ctx.beginPath(); ctx.moveTo(o[0], o[1]);
    ctx.lineTo(o[0] + 25 * u[0], o[1] - 25 * u[1]); ctx.stroke();
    ctx.fillText(name, o[0] + 30 * u[0] - 10, o[1] - 30 * u[1] + 4);
  });
}
// labels in order of importance; one that would cover a label already placed is left out
function labels(pts) {
  const placed = [];
  ctx.fillStyle = "#222222";
  for (const k of M.labelled) {
    const x = pts[k][0] + 8, y = pts[k][1] - 8, w = ctx.measureText(M.names[k]).width;
    const box = [x, y - 12, x + w, y];
    if (placed.some(b => box[0] < b[2] && b[0] < box[2] && box[1] < b[3] && b[1] < box[3]))
      continue;
    placed.push(box); ctx.fillText(M.names[k], x, y);
  }
}
// a following view moves over a grid fixed in N, every fifth line darker
function grid() {
  if (!M.grid) return;
  const [i, j] = M.grid.axes, k = 3 - i - j, step = M.grid.step;
  ctx.lineWidth = 1;
  for (const [a, b] of [[i, j], [j, i]]) {
    const last = Math.floor((mid[a] + span) / step);
    for (let n = Math.ceil((mid[a] - span) / step); n <= last; n++) {
      const p = [0, 0, 0], q = [0, 0, 0];
      p[a] = q[a] = n * step; p[b] = mid[b] - span; q[b] = mid[b] + span;
      p[k] = q[k] = M.grid.level;
      ctx.strokeStyle = M.gridColours[n % 5 === 0 ? 1 : 0];
      ctx.beginPath(); ctx.moveTo(...project(p)); ctx.lineTo(...project(q)); ctx.stroke();
    }
  }
}
function draw() {
  ctx.fillStyle = "#ffffff"; ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.font = "12px sans-serif";
  mid = M.centres[frame];
  grid();
  const pts = M.xyz[frame].map(project);
  ctx.lineWidth = 3;
  M.edges.forEach(([a, b], n) => {
    ctx.strokeStyle = M.colours[M.kinds[n]];
    ctx.beginPath(); ctx.moveTo(...pts[a]); ctx.lineTo(...pts[b]); ctx.stroke(); });
  pts.forEach((p, k) => {
    const center = M.centers.includes(k);
    ctx.fillStyle = center ? "#d62728" : "#ff7f0e";
    ctx.beginPath(); ctx.arc(p[0], p[1], center ? 7 : 4, 0, 2 * Math.PI); ctx.fill();
  });
  labels(pts);
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
    return write_whole(Path(path), html_page(m, title))


def html_page(m: Motion, title: str) -> str:
    """The self-contained page of the motion: a 3-D view to rotate, a time slider."""
    centres, width = m.view()
    data = {"frame": m.frame, "names": m.names, "edges": m.edges, "kinds": m.kinds,
            "colours": COLOURS, "centers": m.centers, "labelled": m.labelled,
            "times": [float(t) for t in m.times], "planar": m.planar, "yaw": YAW,
            "pitch": PITCH, "centres": np.round(centres, 12).tolist(), "span": width,
            "grid": m.grid(), "gridColours": [GRID_COLOURS[False], GRID_COLOURS[True]],
            "axes": m.basis.T.tolist(),
            "xyz": np.round(m.picture, 12).tolist()}
    return PAGE.replace("@TITLE@", html.escape(title)).replace("@DATA@", _script_json(data))


# -- GIF and MP4 ------------------------------------------------------------------------------
def screen(planar: bool, picture) -> np.ndarray:
    """(..., 2): where the movie draws points given in picture coordinates: seen face on
    when planar, else turned by YAW about up and PITCH about right (as the page starts)."""
    p = np.asarray(picture, dtype=float)
    if planar:
        return p[..., :2].copy()
    return np.stack(_turned(p, YAW, PITCH)[:2], axis=-1)


def _turned(p, yaw, pitch):
    """Picture coordinates turned by yaw about up, then by pitch about right: (right,
    up, toward the viewer) on the screen (as the page's turn())."""
    x1 = np.cos(yaw) * p[..., 0] + np.sin(yaw) * p[..., 2]
    z1 = -np.sin(yaw) * p[..., 0] + np.cos(yaw) * p[..., 2]
    return (x1, np.cos(pitch) * p[..., 1] - np.sin(pitch) * z1,
            np.sin(pitch) * p[..., 1] + np.cos(pitch) * z1)


def _corner_axes(ax, m: Motion, aspect: float) -> None:
    """N's axes in the lower left corner; one along the line of sight is a dot (toward
    the viewer) or a cross, named on the side away from the other two."""
    o = np.array([0.07, 0.07])
    turned = [np.array(_turned(v, 0, 0) if m.planar else _turned(v, YAW, PITCH))
              for v in m.basis.T]
    style = {"color": "#888888", "fontsize": 8, "transform": ax.transAxes,
             "ha": "center", "va": "center"}
    for k, u in enumerate(turned):
        name = f"{m.frame}{k + 1}>"
        if np.hypot(u[0], u[1]) < 0.2:
            away = -sum(v[:2] for j, v in enumerate(turned) if j != k)
            away = away / (np.linalg.norm(away) or 1.0)
            ax.text(*o, "\u2299" if u[2] > 0 else "\u2297", **style)
            ax.text(*(o + 0.035 * away * [1, aspect]), name, **style)
            continue
        tip = o + 0.05 * u[:2] * [1, aspect]
        ax.plot([o[0], tip[0]], [o[1], tip[1]], lw=1, color="#888888",
                transform=ax.transAxes)
        ax.text(*(o + 0.075 * u[:2] * [1, aspect]), name, **style)


def shown_labels(boxes) -> list[bool]:
    """Which labels are drawn, given their boxes (x0, y0, x1, y1) in order of importance:
    each one that covers none already drawn (the page does the same)."""
    placed, shown = [], []
    for box in boxes:
        free = not any(box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3]
                       for b in placed)
        shown.append(free)
        if free:
            placed.append(box)
    return shown


def write_movie(m: Motion, path: Path, fps: int = 25, progress=None) -> Path:
    """A GIF (Pillow, which matplotlib brings) or an MP4 (needs ffmpeg) by the suffix;
    `progress`: a stream for progress lines (None: quiet)."""
    from matplotlib import animation as mpl_animation
    path = Path(path)
    mp4 = path.suffix.lower() == ".mp4"
    if mp4 and not mpl_animation.FFMpegWriter.isAvailable():
        raise AutolevModelError("an MP4 needs ffmpeg, which is not installed; write a "
                                "GIF or the HTML page instead")
    # as `autolev run` shows its integration's: a line redrawn in place on a terminal
    report = Progress(progress, path.name, 0, len(m.times), says=FRAMES)
    frames = _frames(m, report)
    if mp4:
        _write_mp4(frames, path, fps)
    else:
        _write_gif(frames, path, fps)
    report.done()
    return path


def _write_gif(frames, path: Path, fps: int) -> None:
    from PIL import Image
    images, palette, index_of = [], None, {}
    for rgb in frames:
        if palette is None:                  # the colours of the first frame: all there are
            first = Image.fromarray(rgb).quantize(colors=64, dither=Image.Dither.NONE)
            palette = np.array(first.getpalette()[:3 * 64], dtype=float).reshape(-1, 3)
        # each colour to its nearest in the palette (Pillow's own mapping is coarser)
        packed = (rgb[:, :, 0].astype(np.int32) << 16) | (rgb[:, :, 1].astype(np.int32) << 8) \
            | rgb[:, :, 2]
        colours, where = np.unique(packed, return_inverse=True)
        new = [c for c in colours.tolist() if c not in index_of]
        if new:
            found = np.array([[c >> 16, (c >> 8) & 255, c & 255] for c in new], dtype=float)
            nearest = np.argmin(((found[:, None] - palette[None]) ** 2).sum(axis=2), axis=1)
            index_of.update(zip(new, nearest.tolist()))
        indices = np.array([index_of[c] for c in colours.tolist()], dtype=np.uint8)
        image = Image.frombytes("P", (rgb.shape[1], rgb.shape[0]), indices[where].tobytes())
        image.putpalette(palette.astype(np.uint8).ravel().tolist())
        images.append(image)
    movie = io.BytesIO()
    images[0].save(movie, format="GIF", save_all=True, append_images=images[1:], loop=0,
                   duration=round(1000 / fps))
    write_whole(path, movie.getvalue())


def _write_mp4(frames, path: Path, fps: int) -> None:
    import itertools
    import subprocess

    import matplotlib
    first = next(frames)
    height, width = first.shape[:2]
    aside = temporary_beside(path)              # renamed over the target once whole
    command = [matplotlib.rcParams["animation.ffmpeg_path"], "-n", "-loglevel", "error",
               "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{width}x{height}",
               "-r", str(fps), "-i", "-", "-pix_fmt", "yuv420p", "-vcodec", "libx264",
               "-f", "mp4", str(aside)]
    try:
        with subprocess.Popen(command, stdin=subprocess.PIPE,
                              stderr=subprocess.PIPE) as ffmpeg:
            for rgb in itertools.chain([first], frames):
                ffmpeg.stdin.write(rgb.tobytes())
            _, errors = ffmpeg.communicate()
        if ffmpeg.returncode:
            raise AutolevModelError(f"ffmpeg could not write {path.name}: "
                                    + errors.decode(errors="replace").strip()[-300:])
        os.replace(aside, path)
    finally:
        aside.unlink(missing_ok=True)


def _frames(m: Motion, report: Progress):
    """The movie's frames as RGB arrays: the still parts drawn once, each frame's grid,
    segments and points drawn over them by matplotlib, its labels and time by Pillow
    (matplotlib's text is most of the time a frame takes)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.font_manager import FontProperties, findfont
    from PIL import Image, ImageDraw, ImageFont

    fig = plt.figure(figsize=(6, 6), dpi=80)
    left, bottom, width, height = 0.02, 0.02, 0.86, 0.86   # labels may pass the top right
    ax = fig.add_axes([left, bottom, width, height])
    ax.set_axis_off()
    planar = m.planar
    centres, view_width = m.view()
    ground = m.grid()
    at = screen(planar, centres)              # where the view's centre is drawn
    xy = screen(planar, m.picture) - at[:, None]
    reach = np.abs(xy).max(axis=(0, 1)) * (1 + MARGIN) if xy.size else np.ones(2)
    aspect = width / height                   # the axes' width over their height
    half_y = max(reach[0] / aspect, reach[1], 1e-12)
    ax.set_xlim(-half_y * aspect, half_y * aspect)
    ax.set_ylim(-half_y, half_y)
    _corner_axes(ax, m, aspect)
    grid = LineCollection([], linewidths=1, animated=True)
    ax.add_collection(grid)
    lines = LineCollection([], linewidths=3, colors=[COLOURS[k] for k in m.kinds],
                           animated=True)
    ax.add_collection(lines)
    others = [k for k in range(len(m.names)) if k not in set(m.centers)]
    dots = ax.plot([], [], "o", color="#ff7f0e", ms=5, animated=True)[0]
    centers = ax.plot([], [], "o", color="#d62728", ms=9, animated=True)[0]
    fig.canvas.draw()
    background = fig.canvas.copy_from_bbox(fig.bbox)
    font_file = findfont(FontProperties(family=["sans-serif"]))
    font = ImageFont.truetype(font_file, round(9 * fig.dpi / 72))
    title_font = ImageFont.truetype(font_file, round(11 * fig.dpi / 72))
    sizes = [font.getbbox(m.names[k])[2:] for k in m.labelled]
    offset = 6 * fig.dpi / 72                  # the labels' offset from their point, pixels
    tall = fig.canvas.get_width_height()[1]
    try:
        for n in range(len(m.times)):
            fig.canvas.restore_region(background)
            p = xy[n]
            lines_now = grid_lines(ground, centres[n], view_width)
            grid.set_segments([screen(planar, ends) - at[n] for ends, _ in lines_now])
            grid.set_color([GRID_COLOURS[major] for _, major in lines_now])
            lines.set_segments([[p[a], p[b]] for a, b in m.edges])
            dots.set_data(p[others, 0], p[others, 1])
            centers.set_data(p[m.centers, 0], p[m.centers, 1])
            for artist in (grid, lines, dots, centers):
                ax.draw_artist(artist)
            image = Image.frombuffer("RGBA", fig.canvas.get_width_height(),
                                     fig.canvas.buffer_rgba()).convert("RGB")
            draw = ImageDraw.Draw(image)
            pixels = ax.transData.transform(p) if len(p) else p   # from the lower left
            boxes = [(pixels[k, 0] + offset, pixels[k, 1] + offset,
                      pixels[k, 0] + offset + size[0], pixels[k, 1] + offset + size[1])
                     for k, size in zip(m.labelled, sizes)]
            for k, box, shown in zip(m.labelled, boxes, shown_labels(boxes)):
                if shown:
                    draw.text((box[0], tall - box[1]), m.names[k], font=font,
                              fill="#222222", anchor="lb")
            draw.text((image.width / 2, 0.05 * tall), f"T = {m.times[n]:.6g}",
                      font=title_font, fill="#000000", anchor="mm")
            yield np.asarray(image)
            report.update(n + 1)
    finally:
        plt.close(fig)
