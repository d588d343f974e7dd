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
* **Joints.** A link written in several frames (P_NO_BO> = L1*A1> + L2/2*B1>) is split
  part by part where each point it passes is known: a point the links already reach by
  that partial sum, or, on a link to a body's mass centre whose last part is in that
  body's frame, the end of a part that runs along a link the model gave from the same
  start, to or beyond that link's end (P_NO_AO> = L1/2*A1>: a joint at L1*A1>).  Such a
  joint is drawn but not labelled (the model never named it); a two-link chain is then
  drawn as a chain and not as a fan from the pivot.
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

The motion is written by animation_output.py: a self-contained HTML page and, with
matplotlib, a GIF or MP4.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import sympy as sm

from ..engine.errors import AutolevModelError
from .numerics.inputs import Inputs, display_name
from .point import Body
from .vectors import Vector

# frames drawn at most: more rows are sampled evenly (the page and the GIF stay small)
MAX_FRAMES = 400
# the margin around the drawn points, as a fraction of their extent
MARGIN = 0.05
# the view follows drawn points that travel farther than this many times their own size
FOLLOW = 3.0
# body triads are this far apart, in units of their own length
TRIAD_SPACING = 2.5
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


def motion(model, result, max_frames: int = MAX_FRAMES, overrides=None) -> Motion:
    """The figure's motion over a run's rows (at most max_frames of them, evenly).
    `overrides` {NAME: value in the quantity's unit}: the values given to the run
    (`--set`), for constants only the figure uses (a drawn link's length)."""
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
                             + [e for g in gravity for e in g.to_matrix(newtonian)],
                             overrides)
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
        notes.append(f"{', '.join(names)} {'has' if one else 'have'} no value (neither "
                     f"INPUT nor --set gives {'it' if one else 'them'} and the run does "
                     f"not need "
                     f"{'it' if one else 'them'}): "
                     + "; ".join(([f"{_some(left_out)} not drawn"] if left_out else [])
                                 + (["down not known from GRAVITY"] if down_unknown else [])))
    points, links = _split_at_joints(points, links)
    exprs = [e for link in links for e in _link_expressions(link.vector, newtonian)]
    exprs += [e for g in gravity for e in g.to_matrix(newtonian)]
    rows = np.unique(np.linspace(0, len(result.t) - 1, min(max_frames, len(result.t)))
                     .round().astype(int))
    times = np.asarray(result.t)[rows]
    evaluate = _evaluator(model, result.system, exprs, "autolev_figure", overrides)
    values = np.array([evaluate(result.t[k], result.states[k]) for k in rows])
    probe = evaluate(result.t[0], _probe_state(result.states[0]))
    down = values[0, 6 * len(links):] if gravity else np.zeros(3)
    if not np.all(np.isfinite(values)):
        raise AutolevModelError("the figure's positions are not finite along the run")
    per_link = values[:, :6 * len(links)].reshape(len(rows), len(links), 6)
    figure = _Figure(model, points, links, per_link, probe[:6 * len(links)])
    triads = not figure.segments and bool(_turning_bodies(model))
    d = _triads(model, result, rows, overrides) if triads else figure.drawing()
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


@dataclass(eq=False)
class _Joint:
    """Where a link's part in one frame ends and its part in the next begins
    (P_NO_BO> = L1*A1> + L2/2*B1>: at L1*A1> from NO); not one of the model's points."""

    name: str


def _split_at_joints(points, links) -> tuple[list, list[_Link]]:
    """Each link with measure numbers in several frames split, part by part in the
    order the model wrote them, where every point it passes is known: a point already
    reached from the link's start by that partial sum (a link's end, or a joint made
    before); or, on a link to a body's mass centre whose last part is in the body's
    frame, a joint at the end of a part that runs along a link the model gave from the
    part's start, in its frame, to or beyond that link's end (P_NO_AO> = L1/2*A1> and
    P_NO_BO> = L1*A1> + L2/2*B1>: a joint at L1*A1>).  Any other link is kept whole (the
    system's mass centre, a weighted sum, passes no joint), and a part that is a link
    already taken is not taken again."""
    points = list(points)
    reached = {}                     # (point, vector's key) -> the point it reaches
    along: dict[int, list] = {}      # point -> the one-frame vectors from it
    for link in links:
        reached[(link.a, _vector_key(link.vector))] = link.b
        reached[(link.b, _vector_key(-link.vector))] = link.a
        if len(link.vector.terms) == 1:
            along.setdefault(link.a, []).append(link.vector)
            along.setdefault(link.b, []).append(-link.vector)
    split = []
    for link in links:
        if len(link.vector.terms) < 2:
            split.append(link)
            continue
        start, end, vector = _toward_mass_centre(link, points)
        frames = list(vector.terms)
        pieces = [Vector({f: vector.terms[f]}) for f in frames]
        joints_allowed = _is_mass_centre_of(points[end], frames[-1])
        ends = []                    # each part's end: a point's index, or None (a joint)
        here, total = start, Vector()
        for k, piece in enumerate(pieces):
            total = total + piece
            there = end if k == len(pieces) - 1 else reached.get((start, _vector_key(total)))
            if there is None and not (joints_allowed and any(
                    _runs_to_or_beyond(piece, v) for v in along.get(here, ()))):
                break
            ends.append(there)
            here = there
        if len(ends) < len(pieces):
            split.append(link)
            continue
        here, total = start, Vector()
        for k, (piece, there) in enumerate(zip(pieces, ends)):
            total = total + piece
            joint = there is None
            if joint:
                there = len(points)
                points.append(_Joint(f"{frames[k].name}/{frames[k + 1].name}"))
            if joint or reached.get((here, _vector_key(piece))) != there:
                reached[(here, _vector_key(piece))] = there
                reached[(there, _vector_key(-piece))] = here
                along.setdefault(here, []).append(piece)
                along.setdefault(there, []).append(-piece)
                split.append(_Link(here, there, piece, _locality(piece)))
            reached.setdefault((start, _vector_key(total)), there)
            here = there
    return points, sorted(split, key=lambda link: link.locality)


def _is_mass_centre_of(point, frame) -> bool:
    return isinstance(frame, Body) and frame.masscenter is point


def _toward_mass_centre(link, points) -> tuple:
    """(start, end, vector from start): the link walked toward its end that is the mass
    centre of the body its first part (walked back) is in, else as the model gave it."""
    frames = list(link.vector.terms)
    if _is_mass_centre_of(points[link.a], frames[0]):
        backward = {f: tuple(-c for c in link.vector.terms[f]) for f in reversed(frames)}
        return link.b, link.a, Vector(backward)
    return link.a, link.b, link.vector


def _runs_to_or_beyond(piece, given) -> bool:
    """Whether `piece` is `given` (both in one frame) times a number of at least 1."""
    (frame, comps), = piece.terms.items()
    if frame not in given.terms:
        return False
    base = given.terms[frame]
    k = next(i for i, c in enumerate(base) if c != 0)
    # cancel decides whether two offsets' measure numbers have a constant ratio: no
    # general simplifier on the way to a picture
    ratio = sm.cancel(comps[k] / base[k])
    return bool(ratio.is_number and ratio.is_real and ratio >= 1 and
                all(sm.expand(c - ratio * b) == 0 for c, b in zip(comps, base)))


def _vector_key(vector) -> tuple:
    """A vector's measure numbers, expanded, by frame: equal for equal sums."""
    return tuple(sorted((id(f), tuple(sm.expand(c) for c in comps))
                        for f, comps in vector.terms.items()))


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
                        {i for i, k in enumerate(order) if self.points[k] in masscenters
                         or isinstance(self.points[k], _Joint)},
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
        if isinstance(p, _Joint):
            continue           # placed by its links only
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


def _triads(model, result, rows, overrides) -> _Drawing:
    """Each body's unit axes over the rows, drawn from one point per body."""
    bodies = _turning_bodies(model)
    every = np.arange(len(result.t))
    axes = []                                              # [.., i, j] = Ni . Bj
    for body, how, exprs in bodies:
        evaluate = _evaluator(model, result.system, exprs, "autolev_triads", overrides)
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


def _evaluator(model, system, exprs, name, overrides):
    """f(t, x) -> values of exprs, with the given values (INPUT, then `overrides`) of the
    constants only they use."""
    return system.evaluator(exprs, name, _geometry_values(model, system, exprs, overrides))


def _given_nowhere(model, system, exprs, overrides) -> set:
    """The constants exprs need that neither the run, nor an INPUT statement, nor
    `overrides` gives."""
    lacking = system.lacking(exprs)
    if not lacking:
        return set()
    return set(_figure_inputs(model, lacking, overrides).missing(lacking))


def _figure_inputs(model, lacking: list, overrides) -> Inputs:
    """The values of the constants only the figure uses: INPUT, then `overrides`."""
    inputs = Inputs(model.defs, lacking, model.inputs, model.unit_of, ())
    for name, value in (overrides or {}).items():
        if inputs.lookup(name) is not None:
            inputs.set(name, value)
    return inputs


def _geometry_values(model, system, exprs, overrides) -> dict:
    """Values of the constants only the figure uses (a link length the equations do not
    need), from the model's INPUT statements and `overrides`."""
    lacking = system.lacking(exprs)
    if not lacking:
        return {}
    inputs = _figure_inputs(model, lacking, overrides)
    missing = inputs.missing(lacking)
    if missing:
        raise AutolevModelError("the figure needs values the run does not: "
                                + ", ".join(display_name(k) for k in missing)
                                + " (give them INPUT values in the model, or --set)")
    return {k: inputs.internal(k) for k in lacking}
