"""A stick figure of a model moving over a run.

What is drawn follows rules of this tool (Autolev drew nothing itself):

* **Links.** Every position the model defines (P_A_B> = ...) links A and B.  Links are
  taken most local first: measure numbers in the fewest frames, then the fewest measure
  numbers, then the smallest expressions.  A link between two points that the links
  taken before already join is a *repetition* when its vector is the sum along that
  chain at every state (checked at the run's rows and at a probe state off the run) and
  it is less local than each link of the chain: it is built from them, as a model's
  outputs are (P_O_P2> = P_O_P1> + P_P1_P2>).  Repetitions are left out, so the figure
  is the chain and not a fan from the point every output is measured from.  Any other
  such link closes a loop (a four-bar or parallelogram with its last side positioned)
  and is drawn.
* **Segments.** A link whose length and measure numbers along N's own axes both change
  (over the run or at the probe state) places the figure in N rather than being part of
  it (P_O_P1> = Q1*N1> + Q2*N2>, or P_O_CM> = CM(O) built on it): it is not drawn, nor
  is a link of no length (P_NO_O> = 0>).  Every other link is.
* **Where.** A point fixed in N (NO, or a point whose velocity in N is 0>: V_O_N> = 0>
  or a constant position from NO) anchors the points linked to it.  NO is the picture's
  origin; a part of the figure anchored at another fixed point with no position from
  NO, or with no fixed point at all (then at its first point), is drawn from the origin
  too, with a note.  A fixed point that ends no segment is not drawn (the ground point
  the figure is only placed from).
* **Marks.** Bodies' mass centres and particles are drawn larger; every point but a
  body's mass centre is labelled, the ends of most segments first, and a label that
  would cover one already placed in that frame is left out.
* **No figure.** When there is no segment (a spacecraft with reaction wheels, a body
  at its fixed mass centre), each oriented body's axes are drawn instead, side by
  side: unit lines along B1>, B2>, B3> turning with B's orientation in N.  A body
  whose orientation the model never defines but whose angular velocity in N it does
  (W_B_N> in B's own axes, a torque-free gyrostat) starts along N's axes and turns
  with that angular velocity, integrated over the run's rows.
* **Values given nowhere.** A link (or the GRAVITY that gives down) that needs a
  constant the run does not need and no INPUT gives is left out, with a note; the
  rest is drawn.
* **The view.** Down is where the first GRAVITY statement's vector points, with the
  run's values.  When the drawn points keep their coordinate along an axis of N (a plane
  motion) the picture looks along that axis (the one gravity is not along, N3 before N2
  before N1); otherwise along the axis most nearly level (the same order on a tie).  Up
  is opposite gravity, made square to the line of sight; without gravity (or with it
  along the line of sight) the axes go round: looking along N3, N1 is right and N2 up;
  along N2, N3 right and N1 up; along N1, N2 right and N3 up.  The view is framed on the
  drawn points over the whole run; when they travel farther than FOLLOW times the
  figure's own size (a runner, a bicycle) it follows them instead, centred on their
  centroid in each frame, over a grid fixed in N (in the plane of a plane motion, else
  on the ground under the lowest point) that shows the travel.

It is written as a self-contained HTML page (a 3-D view to rotate with the mouse and a
time slider, no network needed) and, with matplotlib, as a GIF (or an MP4 where ffmpeg
is installed); matplotlib, optional, is imported only where the movie is drawn.
"""
from __future__ import annotations

import html
import io
import json
import math
import os
from time import monotonic
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import sympy as sm

from .runtime.errors import AutolevModelError
from .runtime.numerics.inputs import Inputs, display_name
from .runtime.outputs import temporary_beside, write_whole
from .runtime.vector import Vector

# frames drawn at most: more rows are sampled evenly (the page and the GIF stay small)
MAX_FRAMES = 400
# the margin around the drawn points, as a fraction of their extent
MARGIN = 0.05
# the view follows drawn points that travel farther than this many times their own size
FOLLOW = 3.0
# body triads are this far apart, in units of their own length
TRIAD_SPACING = 2.5
# the 3-D view the GIF is drawn in (the page starts from it too): radians about up, right
YAW, PITCH = 0.6, 0.4
SEGMENT, AXIS_1, AXIS_2, AXIS_3 = 0, 1, 2, 3   # what an edge of the picture is


@dataclass
class Motion:
    """Where every drawn point of the figure is at each drawn time."""

    frame: str                       # the Newtonian frame's name
    names: list[str]                 # the points drawn
    edges: list[tuple[int, int]]     # pairs of point indices
    centers: list[int]               # mass centres and particles (drawn larger)
    times: np.ndarray                # (frames,)
    xyz: np.ndarray                  # (frames, points, 3), in the frame's basis
    kinds: list[int] = field(default_factory=list)     # per edge (default: SEGMENT)
    labelled: list[int] = field(default_factory=list)  # points labelled, most wanted first
    # rows: the picture's right, up and toward-the-viewer directions in N's basis
    basis: np.ndarray = field(default_factory=lambda: np.eye(3))
    notes: list[str] = field(default_factory=list)     # how the figure was placed

    def __post_init__(self):
        if not self.kinds:                   # edges not said otherwise are segments
            self.kinds = [SEGMENT] * len(self.edges)

    @property
    def picture(self) -> np.ndarray:
        """(frames, points, 3): right, up and depth coordinates."""
        return self.xyz @ self.basis.T

    @property
    def planar(self) -> bool:
        """All points stay in one plane facing the viewer."""
        depth = self.picture[:, :, 2]
        if not depth.size:
            return True
        scale = max(1.0, float(np.abs(self.xyz).max()))
        return bool(depth.max() - depth.min() <= 1e-9 * scale)

    def view_box(self) -> tuple[np.ndarray, np.ndarray]:
        """The lowest and highest picture coordinates of the drawn points over the run,
        widened by MARGIN of the largest extent (1 when the points never part)."""
        p = self.picture.reshape(-1, 3)
        if not len(p):
            return -np.ones(3), np.ones(3)
        lo, hi = p.min(axis=0), p.max(axis=0)
        extent = float((hi - lo).max())
        pad = MARGIN * extent if extent > 0 else 1.0
        return lo - pad, hi + pad

    @property
    def follows(self) -> bool:
        """The drawn points travel farther than FOLLOW times the figure's own size (its
        largest extent in one frame): the view goes with them."""
        p = self.picture
        if len(self.names) < 2:
            return False
        size = float(np.ptp(p, axis=1).max())
        travel = float(np.ptp(p.mean(axis=1), axis=0).max())
        return size > 0 and travel > FOLLOW * size

    def view(self) -> tuple[np.ndarray, float]:
        """(frames, 3) centres of the view and its width, in picture coordinates: the
        view box over the whole run, or, when the view follows, each frame's centroid of
        the drawn points and room for the figure's farthest point from it."""
        if self.follows:
            centres = self.picture.mean(axis=1)
            reach = float(np.linalg.norm(self.picture - centres[:, None], axis=2).max())
            return centres, 2 * reach * (1 + 2 * MARGIN)
        lo, hi = self.view_box()
        return np.repeat(((lo + hi) / 2)[None], len(self.times), axis=0), float((hi - lo).max())

    def grid(self) -> dict | None:
        """The grid fixed in N that a following view moves over: its spacing (1, 2 or 5
        times a power of ten, about a quarter of the view), the two picture axes it spans
        and its place along the third (the plane of a plane motion, else the lowest
        point's height: the ground); None for a view that stays put."""
        if not self.follows:
            return None
        _, width = self.view()
        rough = width / 4
        power = 10 ** np.floor(np.log10(rough))
        step = float(min((f * power for f in (1, 2, 5, 10)), key=lambda v: abs(v - rough)))
        p = self.picture
        if self.planar:
            return {"step": step, "axes": [0, 1], "level": float(p[0, 0, 2])}
        return {"step": step, "axes": [0, 2], "level": float(p[:, :, 1].min())}


def grid_lines(grid: dict | None, centre, width: float) -> list:
    """A grid's lines (Motion.grid) within width of centre: (pair of picture points,
    whether it is a major line, every fifth: a figure moving a whole number of steps
    between frames still shows its travel)."""
    if grid is None:
        return []
    i, j = grid["axes"]
    k, step = 3 - i - j, grid["step"]
    lines = []
    for a, b in ((i, j), (j, i)):
        for n in range(int(np.ceil((centre[a] - width) / step)),
                       int(np.floor((centre[a] + width) / step)) + 1):
            ends = np.zeros((2, 3))
            ends[:, a] = n * step
            ends[:, b] = centre[b] - width, centre[b] + width
            ends[:, k] = grid["level"]
            lines.append((ends, n % 5 == 0))
    return lines


@dataclass
class _Link:
    """A position the model defined: P_a_b> = vector (a, b index the located points)."""

    a: int
    b: int
    vector: Vector
    locality: tuple                  # smaller is more local (see _locality)


def motion(model, result, max_frames: int = MAX_FRAMES) -> Motion:
    """The figure's motion over a run's rows (at most max_frames of them, evenly)."""
    if result.system is None or not len(result.t):
        raise AutolevModelError("the run has no rows to animate")
    if len(result.t) != len(result.states):
        raise AutolevModelError("the run kept only its last row (keep_rows=False)")
    newtonian = model.newtonian_frame
    if newtonian is None:
        raise AutolevModelError("no NEWTONIAN frame: there is nothing to draw the motion in")
    points = [p for p in model.points_by_name.values() if p.linked_points()]
    links = _links(points)
    gravity = model.gravity_vectors[:1]
    unknown = _given_nowhere(model, result.system,
                             [e for link in links for e in link.vector.to_matrix(newtonian)]
                             + [e for g in gravity for e in g.to_matrix(newtonian)])
    notes = []
    if unknown:             # leave out what needs them: the rest of the figure is drawn

        def usable(vector) -> bool:
            return not unknown & set(result.system.lacking(list(vector.to_matrix(newtonian))))
        left_out = [f"P_{points[link.a].name}_{points[link.b].name}>" for link in links
                    if not usable(link.vector)]
        points = [p for p in points if any(usable(q.pos_from(p)) for q in p.linked_points())]
        links = _links(points, usable)
        down_unknown = bool(gravity) and not usable(gravity[0])
        gravity = [g for g in gravity if usable(g)]
        names = sorted(display_name(k) for k in unknown)
        one = len(names) == 1
        notes.append(f"{', '.join(names)} {'has' if one else 'have'} no value (no INPUT "
                     f"gives {'it' if one else 'them'} and the run does not need "
                     f"{'it' if one else 'them'}): "
                     + "; ".join(([f"{_some(left_out)} not drawn"] if left_out else [])
                                 + (["down not known from GRAVITY"] if down_unknown else [])))
    exprs = [e for link in links for e in _link_expressions(link.vector, newtonian)]
    exprs += [e for g in gravity for e in g.to_matrix(newtonian)]
    rows = np.unique(np.linspace(0, len(result.t) - 1, min(max_frames, len(result.t)))
                     .round().astype(int))
    times = np.asarray(result.t)[rows]
    evaluate = _evaluator(model, result.system, exprs, "autolev_figure")
    values = np.array([evaluate(result.t[k], result.states[k]) for k in rows])
    probe = evaluate(result.t[0], _probe_state(result.states[0]))
    down = values[0, 6 * len(links):] if gravity else np.zeros(3)
    if not np.all(np.isfinite(values)):
        raise AutolevModelError("the figure's positions are not finite along the run")
    per_link = values[:, :6 * len(links)].reshape(len(rows), len(links), 6)
    figure = _Figure(model, points, links, per_link, probe[:6 * len(links)])
    triads = not figure.segments and bool(_turning_bodies(model))
    d = _triads(model, result, rows) if triads else figure.drawing()
    if not d.names:
        raise AutolevModelError(
            "there is no figure to draw: no positions link the points (P_A_B>) and no body "
            f"has an orientation or angular velocity in {newtonian.name}")
    basis = view_basis(down, d.xyz)
    xyz = d.xyz
    if triads:                                 # side by side, along the picture's right
        xyz = xyz + TRIAD_SPACING * (np.arange(len(d.names)) // 4)[:, None] * basis[0]
    return Motion(newtonian.name, d.names, d.edges, d.centers, times, xyz, d.kinds,
                  d.label_order(), basis, notes + d.notes)


@dataclass
class _Drawing:
    """What is drawn, in N's basis, before the view is chosen."""

    names: list[str]
    xyz: np.ndarray                  # (rows, points, 3)
    edges: list[tuple[int, int]]
    kinds: list[int]
    centers: list[int]               # drawn larger
    unlabelled: set[int]             # bodies' mass centres, triads' origins
    notes: list[str]

    def label_order(self) -> list[int]:
        """The points labelled, the ends of most segments first."""
        ends = np.zeros(len(self.names), dtype=int)
        for (a, b), kind in zip(self.edges, self.kinds):
            if kind == SEGMENT:
                ends[a] += 1
                ends[b] += 1
        return sorted((k for k in range(len(self.names)) if k not in self.unlabelled),
                      key=lambda k: -ends[k])


# -- the links and the figure they make ------------------------------------------------------
def _links(points, usable=None) -> list[_Link]:
    """Each position between the points defined once (and `usable`), most local first."""
    index = {p: k for k, p in enumerate(points)}
    found = []
    for a, p in enumerate(points):
        for q in p.linked_points():
            if index.get(q, -1) > a:
                vector = q.pos_from(p)
                if usable is None or usable(vector):
                    found.append(_Link(a, index[q], vector, _locality(vector)))
    return sorted(found, key=lambda link: link.locality)


def _locality(vector) -> tuple:
    """How local a link is: frames its measure numbers are in, how many measure numbers,
    how large their expressions are."""
    comps = [c for cs in vector.terms.values() for c in cs if c != 0]
    # a link's size is the same either way along it: P_Q_R> = -P_R_Q>
    size = sum(sm.count_ops(-c if c.could_extract_minus_sign() else c) for c in comps)
    return len(vector.terms), len(comps), size


def _link_expressions(vector, newtonian) -> list:
    """A link's vector in N's basis, then its measure numbers along N's own axes."""
    return list(vector.to_matrix(newtonian)) + list(vector.terms.get(newtonian, (0, 0, 0)))


def _probe_state(x) -> np.ndarray:
    """A state off the run: each state moved by 0.1 + 10 % of its size, in directions
    that follow no pattern of a model (a repetition holds there, a closed loop does not)."""
    x = np.asarray(x, dtype=float)
    return x + (0.1 + 0.1 * np.abs(x)) * np.sin(np.arange(1, len(x) + 1) * 2.39996)


class _Figure:
    """The links of a run sorted into a tree, loops and repetitions; where each point is."""

    def __init__(self, model, points, links, per_link, probe):
        self.model = model
        self.points = points
        self.links = links
        vectors = per_link[:, :, :3]                       # (rows, links, 3)
        self.vectors = vectors
        self.tolerance = 1e-9 * (1.0 + float(np.abs(vectors).max(initial=0.0)))
        # what holds at every state is judged at the rows and at the probe (when finite):
        # a run where the figure stands still still tells a rod from a translation
        probe = probe.reshape(1, len(links), 6)
        samples = np.concatenate([probe, per_link]) if np.all(np.isfinite(probe)) \
            else per_link
        self.tree, self.loops = self._sort(samples[:, :, :3])
        lengths = np.linalg.norm(samples[:, :, :3], axis=2)    # (samples, links)
        along_n = samples[:, :, 3:]
        self.placing = {k for k in range(len(links))
                        if np.ptp(lengths[:, k]) > self.tolerance
                        and np.ptp(along_n[:, k], axis=0).max() > self.tolerance}
        # a link of no length at any time joins a point to itself: nothing to draw
        drawn_lengths = np.linalg.norm(vectors, axis=2)
        self.segments = [k for k in self.tree + self.loops if k not in self.placing
                         and drawn_lengths[:, k].max() > self.tolerance]
        self.fixed = _fixed_points(model, points)
        self.parts: list[list[int]] = []     # the points joined by the tree, anchor first
        self.notes: list[str] = []
        self.xyz = self._place()

    def _sort(self, samples) -> tuple[list[int], list[int]]:
        """Links of the tree and of closed loops; the rest repeat a chain."""
        adjacent: dict[int, list[tuple[int, int]]] = {k: [] for k in range(len(self.points))}
        tree, loops = [], []
        for n, link in enumerate(self.links):
            chain = _path(adjacent, link.a, link.b)
            if chain is None:
                tree.append(n)
                adjacent[link.a].append((link.b, n))
                adjacent[link.b].append((link.a, -n - 1))
                continue
            along = sum(samples[:, m] if m >= 0 else -samples[:, -m - 1] for m in chain)
            repeats = np.abs(along - samples[:, n]).max(initial=0.0) <= 10 * self.tolerance
            built = all(self.links[m if m >= 0 else -m - 1].locality < link.locality
                        for m in chain)
            if not (repeats and built):
                loops.append(n)
        return tree, loops


    def _place(self) -> np.ndarray:
        """(rows, points, 3): every point from its part's anchor along the tree."""
        adjacent: dict[int, list[tuple[int, int]]] = {k: [] for k in range(len(self.points))}
        for n in self.tree:
            link = self.links[n]
            adjacent[link.a].append((link.b, n))
            adjacent[link.b].append((link.a, -n - 1))
        xyz = np.zeros((self.vectors.shape[0], len(self.points), 3))
        origin = self.model.newtonian_frame.declared_origin
        placed: set[int] = set()
        for k, point in sorted(enumerate(self.points), key=lambda kp: self._anchor_rank(kp[1])):
            if k in placed:
                continue
            part, queue = [k], [k]
            placed.add(k)
            while queue:
                here = queue.pop(0)
                for there, n in sorted(adjacent[here]):
                    if there not in placed:
                        v = self.vectors[:, n] if n >= 0 else -self.vectors[:, -n - 1]
                        xyz[:, there] = xyz[:, here] + v
                        placed.add(there)
                        part.append(there)
                        queue.append(there)
            self.parts.append(part)
            if point is not origin and point not in self.fixed:
                self.notes.append(f"no point of {_some(self.points[j].name for j in part)} "
                                  f"is fixed in N: drawn with {point.name} at the origin")
        anchored = [self.points[part[0]].name for part in self.parts
                    if self.points[part[0]] is not origin and self.points[part[0]] in self.fixed]
        if anchored and len(self.parts) > 1:
            self.notes.append(f"{_some(anchored)} {'is' if len(anchored) == 1 else 'are'} "
                              f"fixed in N with no position from {self.model.newtonian_frame.name}O"
                              " or each other: drawn at the origin")
        return xyz

    def _anchor_rank(self, point) -> tuple:
        """NO first, then other fixed points, then the rest, each in the model's order."""
        origin = self.model.newtonian_frame.declared_origin
        return (point is not origin, point not in self.fixed)

    def drawing(self) -> _Drawing:
        """The drawn points: the ends of segments and every point not fixed in N."""
        ends = {k for n in self.segments for k in (self.links[n].a, self.links[n].b)}
        order = [k for part in self.parts for k in part
                 if k in ends or self.points[k] not in self.fixed]
        index = {k: i for i, k in enumerate(order)}
        edges = sorted((min(index[self.links[n].a], index[self.links[n].b]),
                        max(index[self.links[n].a], index[self.links[n].b]))
                       for n in self.segments)
        masscenters = {b.masscenter for b in self.model.bodies_list}
        heavy = masscenters | set(self.model.particles_list)
        return _Drawing([self.points[k].name for k in order], self.xyz[:, order], edges,
                        [SEGMENT] * len(edges),
                        [i for i, k in enumerate(order) if self.points[k] in heavy],
                        {i for i, k in enumerate(order) if self.points[k] in masscenters},
                        self.notes)


def _path(adjacent, start: int, end: int) -> list[int] | None:
    """The links from start to end through the tree (k for link k walked from a to b,
    -k - 1 walked back), or None when they are not joined."""
    came = {start: None}
    queue = [start]
    while queue:
        here = queue.pop(0)
        if here == end:
            steps = []
            while came[here] is not None:
                here, step = came[here]
                steps.append(step)
            return steps[::-1]
        for there, step in adjacent[here]:
            if there not in came:
                came[there] = (here, step)
                queue.append(there)
    return None


def _some(names) -> str:
    names = list(names)
    shown = ", ".join(names[:4])
    return shown if len(names) <= 4 else f"{shown} and {len(names) - 4} more"


def _fixed_points(model, points) -> set:
    """The points whose velocity in N is 0>: NO, an assigned V_O_N> = 0>, or a constant
    position from a point fixed in N."""
    newtonian = model.newtonian_frame
    fixed = set()
    for p in points:
        if p is newtonian.declared_origin:
            fixed.add(p)
        elif p.has_vel(newtonian):
            try:
                if not p.vel(newtonian).terms:
                    fixed.add(p)
            except AutolevModelError:
                continue           # a velocity the model cannot form: not known to be fixed
    return fixed


def _turning_bodies(model) -> list:
    """(body, how its axes are found) for each body whose axes can be drawn: its
    direction cosines with N where its orientation is defined, else its angular velocity
    in N in its own basis (integrated over the run)."""
    newtonian = model.newtonian_frame
    found = []
    for body in model.bodies_list:
        if newtonian.orientation_known(body):
            found.append((body, "dcm", list(newtonian.dcm(body))))
            continue
        try:
            rate = list(body.ang_vel_in(newtonian).to_matrix(body))
        except AutolevModelError:
            continue           # no angular velocity, or one not in terms of its own axes
        found.append((body, "rate", rate))
    return found


def _triads(model, result, rows) -> _Drawing:
    """Each body's unit axes over the rows, drawn from one point per body."""
    bodies = _turning_bodies(model)
    every = np.arange(len(result.t))
    axes = []                                              # [.., i, j] = Ni . Bj
    for body, how, exprs in bodies:
        evaluate = _evaluator(model, result.system, exprs, "autolev_triads")
        if how == "dcm":
            axes.append(np.array([evaluate(result.t[k], result.states[k]) for k in rows])
                        .reshape(len(rows), 3, 3))
        else:
            rates = np.array([evaluate(result.t[k], result.states[k]) for k in every])
            axes.append(_turned_by(rates, np.asarray(result.t, dtype=float))[rows])
    names, xyz, edges = [], [], []
    for n, (body, _, _) in enumerate(bodies):
        names += [body.name] + [f"{body.name}{j}>" for j in (1, 2, 3)]
        xyz += [np.zeros((len(rows), 3))] + [axes[n][:, :, j] for j in range(3)]
        edges += [(4 * n, 4 * n + j) for j in (1, 2, 3)]
    notes = [f"{body.name}'s orientation in {model.newtonian_frame.name} is not defined: its "
             "axes start along N's and turn with its angular velocity"
             for body, how, _ in bodies if how == "rate"]
    return _Drawing(names, np.stack(xyz, axis=1), edges, [AXIS_1, AXIS_2, AXIS_3] * len(bodies),
                    [], set(range(0, 4 * len(bodies), 4)), notes)


def _turned_by(rates, times) -> np.ndarray:
    """(rows, 3, 3) direction cosines N_B from the identity at the first row, B turning
    with the angular velocity `rates` (rows, 3) in its own basis: dN_B/dt = N_B [w x],
    each step turned exactly by the mean of the rates at its ends."""
    out = np.empty((len(times), 3, 3))
    out[0] = np.eye(3)
    for k in range(1, len(times)):
        turn = 0.5 * (rates[k - 1] + rates[k]) * (times[k] - times[k - 1])
        angle = float(np.linalg.norm(turn))
        cross = np.array([[0, -turn[2], turn[1]], [turn[2], 0, -turn[0]],
                          [-turn[1], turn[0], 0]])
        step = np.eye(3)
        if angle > 0:          # Rodrigues: exp([v x]) for v = turn
            step += (math.sin(angle) / angle) * cross \
                + ((1 - math.cos(angle)) / angle ** 2) * cross @ cross
        out[k] = out[k - 1] @ step
    return out


def view_basis(down, xyz) -> np.ndarray:
    """Rows: the picture's right, up and depth directions in N's basis (see the module's
    rules)."""
    axes = np.eye(3)
    flat = xyz.reshape(-1, 3)
    scale = max(1.0, float(np.abs(flat).max(initial=0.0)))
    spread = np.ptp(flat, axis=0) if len(flat) else np.zeros(3)
    g = np.asarray(down, dtype=float)
    g = g / np.linalg.norm(g) if np.linalg.norm(g) > 0 else np.zeros(3)
    preference = (2, 1, 0)                   # N3, N2, N1
    normals = [k for k in preference if spread[k] <= 1e-9 * scale]
    if normals:                              # a plane motion, face on; gravity in it if can be
        depth = axes[([k for k in normals if abs(g[k]) < 1 - 1e-9] or normals)[0]]
    else:
        depth = axes[min(preference, key=lambda k: (round(abs(g[k]), 12), preference.index(k)))]
    up = -(g - np.dot(g, depth) * depth)
    if np.linalg.norm(up) < 1e-9:
        k = int(np.argmax(depth))
        up = axes[(k + 2) % 3]               # the axes going round: N3 -> N2 up
    up = up / np.linalg.norm(up)
    return np.array([np.cross(up, depth), up, depth])


def _evaluator(model, system, exprs, name):
    """f(t, x) -> values of exprs, with INPUT values for constants only they use."""
    return system.evaluator(exprs, name, _geometry_values(model, system, exprs))


def _given_nowhere(model, system, exprs) -> set:
    """The constants exprs need that neither the run nor an INPUT statement gives."""
    lacking = system.lacking(exprs)
    return set(Inputs(model, lacking, ()).missing(lacking)) if lacking else set()


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
    centres, width = m.view()
    data = {"frame": m.frame, "names": m.names, "edges": m.edges, "kinds": m.kinds,
            "colours": COLOURS, "centers": m.centers, "labelled": m.labelled,
            "times": [float(t) for t in m.times], "planar": m.planar, "yaw": YAW,
            "pitch": PITCH, "centres": np.round(centres, 12).tolist(), "span": width,
            "grid": m.grid(), "gridColours": [GRID_COLOURS[False], GRID_COLOURS[True]],
            "axes": m.basis.T.tolist(),
            "xyz": np.round(m.picture, 12).tolist()}
    page = PAGE.replace("@TITLE@", html.escape(title)).replace("@DATA@", _script_json(data))
    return write_whole(Path(path), page)


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


class _Progress:
    """A line on a stream while frames are drawn, as `autolev run` shows its
    integration's: after a second, every 0.2 s on a terminal (in place) or 5 s otherwise."""

    def __init__(self, stream, what: str, total: int):
        self.stream, self.what, self.total = stream, what, total
        self.start = monotonic()
        self.last = float("-inf")
        self.shown = False
        self.tty = stream is not None and stream.isatty()

    def update(self, done: int) -> None:
        now = monotonic()
        if self.stream is None or now - self.start < 1.0 or \
                now - self.last < (0.2 if self.tty else 5.0):
            return
        self.last = now
        text = (f"  {self.what}: frame {done} of {self.total} "
                f"({100 * done / self.total:.0f}%), {now - self.start:.1f} s")
        self.stream.write("\r" + text + "   " if self.tty else text + "\n")
        self.stream.flush()
        self.shown = True

    def done(self) -> None:
        if self.shown and self.tty:
            self.stream.write("\n")
            self.stream.flush()


def write_movie(m: Motion, path: Path, fps: int = 25, progress=None) -> Path:
    """A GIF (Pillow, which matplotlib brings) or an MP4 (needs ffmpeg) by the suffix;
    `progress`: a stream for progress lines (None: quiet)."""
    from matplotlib import animation as mpl_animation
    path = Path(path)
    mp4 = path.suffix.lower() == ".mp4"
    if mp4 and not mpl_animation.FFMpegWriter.isAvailable():
        raise AutolevModelError("an MP4 needs ffmpeg, which is not installed; write a "
                                "GIF or the HTML page instead")
    report = _Progress(progress, path.name, len(m.times))
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


def _frames(m: Motion, report: _Progress):
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
