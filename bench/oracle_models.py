"""Random multibody models for bench/oracle.py: the plain description (dataclasses), the
generator of each family, and the two writers of a description -- Autolev text, and a
sympy.physics.mechanics script that builds the same system directly with KanesMethod.

A description is a tree of links hung from the Newtonian frame N (or from a rolling
disc), each link a rigid body or a particle reached through a joint: a point at a
constant offset in its parent's frame, slides along the parent's axes (one coordinate
each) and a rotation (SIMPROT, DIRCOS or Euler parameters), then the mass point at a
constant offset in the link's frame.  Loads (gravity, forces and torques alone or as
action and reaction, springs with dampers), motion constraints (DEPENDENT or
AUXILIARY, each a point's velocity along a direction) and auxiliary speeds complete it.
Every constant has a value; both writers read the same values.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field

# Scalars are small trees of tuples, written in either language:
# ("c", name) a constant, ("n", text) a number, ("q", k), ("u", k), ("t",) time,
# ("sin", e), ("cos", e), ("*", a, b), ("neg", e).  A vector is a tuple of terms
# (scalar or None for 1, frame name, axis 1..3).

XYZ = "xyz"


def autolev_scalar(e) -> str:
    kind = e[0]
    if kind in ("c", "n"):
        return e[1]
    if kind == "q":
        return f"Q{e[1]}"
    if kind == "u":
        return f"U{e[1]}"
    if kind == "t":
        return "T"
    if kind in ("sin", "cos"):
        return f"{kind.upper()}({autolev_scalar(e[1])})"
    if kind == "neg":
        return f"-{autolev_scalar(e[1])}"
    return f"{autolev_scalar(e[1])}*{autolev_scalar(e[2])}"


def sympy_scalar(e) -> str:
    kind = e[0]
    if kind in ("c", "n"):
        return e[1]
    if kind == "q":
        return f"q{e[1]}"
    if kind == "u":
        return f"u{e[1]}"
    if kind == "t":
        return "t"
    if kind in ("sin", "cos"):
        return f"sm.{kind}({sympy_scalar(e[1])})"
    if kind == "neg":
        return f"-{sympy_scalar(e[1])}"
    return f"{sympy_scalar(e[1])}*{sympy_scalar(e[2])}"


def autolev_vector(terms) -> str:
    if not terms:
        return "0>"
    text = ""
    for scalar, frame, axis in terms:
        unit = f"{frame}{axis}>"
        term = unit if scalar is None else f"{autolev_scalar(scalar)}*{unit}"
        # a negative term is subtracted: no "+ -" in the text
        sign = "" if not text else (" - " if term.startswith("-") else " + ")
        text += sign + (term[1:] if text and term.startswith("-") else term)
    return text


def sympy_vector(terms) -> str:
    if not terms:
        return "me.Vector(0)"
    parts = []
    for scalar, frame, axis in terms:
        unit = f"{frame}.{XYZ[axis - 1]}"
        parts.append(unit if scalar is None else f"{sympy_scalar(scalar)}*{unit}")
    return " + ".join(parts)


# -- the description ----------------------------------------------------------------------

@dataclass
class Rotation:
    kind: str                  # "simprot", "dircos" or "euler"
    axis: object = 3           # SIMPROT: +-1, +-2, +-3, or a vector (terms in the parent)
    sequence: str = ""         # DIRCOS: BODY123, SPACE313, ...
    # "qdot": q' = u, W implied by the orientation; "w": q' = u, W_B_A> written out in u;
    # "child" / "parent": W_B_A> = u1*X1> + u2*X2> + u3*X3> of the child's / parent's
    # unit vectors, the q' from KINDIFFS
    speeds: str = "qdot"
    q: tuple = ()
    u: tuple = ()


@dataclass
class Link:
    number: int
    kind: str                  # "body" or "particle"
    parent: int                # 0: N; else the parent link's number
    offset: tuple              # joint point from the parent's mass point, in its frame
    slides: tuple = ()         # (axis, q, u): the joint slides along the parent's axes
    rotation: Rotation | None = None
    mass_offset: tuple = ()    # mass point from the joint point, in the link's frame
    velocity: str = "theory"   # how Autolev is given velocities: theory, dt or implied
    aux: tuple | None = None   # (speed number, direction terms): a slack joint's speed
    inertia: tuple = ()        # I11, I22, I33[, I12, I23, I31]: constant names or numbers

    @property
    def frame(self) -> str | None:
        """The link's own frame, None when it turns with its parent."""
        if self.rotation is None:
            return None
        return f"B{self.number}" if self.kind == "body" else f"F{self.number}"

    @property
    def mass_point(self) -> str:
        return f"B{self.number}O" if self.kind == "body" else f"P{self.number}"

    @property
    def joint(self) -> str:
        return f"J{self.number}"

    @property
    def aux_point(self) -> str:
        return f"JA{self.number}"


@dataclass
class Disc:
    """A disc (body DC, radius RD) rolling on the plane of N1> and N2>: yaw DA, lean DB,
    spin DC by SIMPROT; Q4, Q5 locate the contact DN, whose speeds are dependent."""
    speeds: str = "qdot"       # "qdot" or "w" (the angular velocities written out)
    q: tuple = (1, 2, 3, 4, 5)
    u: tuple = (1, 2, 3, 4, 5)


@dataclass
class Load:
    kind: str                  # force, force_pair, torque, torque_pair, spring
    on: tuple                  # points (forces, springs) or frames (torques); reaction first
    vector: tuple = ()
    constants: tuple = ()      # a spring's stiffness, natural length, damping


@dataclass
class Constraint:
    kind: str                  # "dependent" or "auxiliary"
    point: str                 # the point whose velocity is constrained
    direction: tuple           # terms
    speed: int                 # the speed the constraint is solved for
    written: str = "velocity"  # "velocity": DOT(V_X_N>, d); "dt": DT(DOT(P_NO_X>, d))
    force: str | None = None   # a noncontributing force along d at the point, KANE's unknown


@dataclass
class Description:
    family: str
    links: list = field(default_factory=list)
    disc: Disc | None = None
    gravity: tuple = ()
    loads: list = field(default_factory=list)
    constraints: list = field(default_factory=list)
    aux_slides: list = field(default_factory=list)   # (link, axis, q, u, force): u auxiliary
    constants: dict = field(default_factory=dict)    # name -> value text
    anchors: dict = field(default_factory=dict)      # spring anchors fixed in N: name -> terms
    ranges: dict = field(default_factory=dict)       # coordinate/speed name -> (low, high)
    quaternions: list = field(default_factory=list)  # the Euler parameters' names, by fours
    multipliers: bool = False  # the constraint forces by the unconstrained system's equations
    nq: int = 0
    nu: int = 0
    naux: int = 0

    # -- names ----------------------------------------------------------------------
    def link(self, number: int) -> Link:
        return self.links[number - 1 - (self.disc is not None)]

    def frame_of(self, number: int) -> str:
        """The frame children of link `number` hang from (0: N; the disc's DC)."""
        if number == 0:
            return "N"
        if self.disc is not None and number == 1:
            return "DC"
        link = self.link(number)
        return link.frame or self.frame_of(link.parent)

    def point_of(self, number: int) -> str:
        if number == 0:
            return "NO"
        if self.disc is not None and number == 1:
            return "DCO"
        return self.link(number).mass_point

    def unknowns(self) -> list:
        out = [link_force(link) for link in self.links if link.aux]
        out += [s[4] for s in self.aux_slides]
        out += [c.force for c in self.constraints if c.force]
        return out

    def auxiliary_speeds(self) -> list:
        """Autolev names of the auxiliary speeds, in CONSTRAIN order."""
        out = [f"UA{link.aux[0]}" for link in self.links if link.aux]
        out += [f"U{s[3]}" for s in self.aux_slides]
        out += [f"U{c.speed}" for c in self.constraints if c.kind == "auxiliary"]
        return out

    def dependent_speeds(self) -> list:
        return [f"U{c.speed}" for c in self.constraints if c.kind == "dependent"]

    def bodies(self) -> list:
        out = [link.frame for link in self.links if link.kind == "body"]
        return (["DC"] if self.disc else []) + out

    def particles(self) -> list:
        return [link.mass_point for link in self.links if link.kind == "particle"]

    def frames(self) -> list:
        out = [link.frame for link in self.links if link.kind == "particle" and link.frame]
        return (["DA", "DB"] if self.disc else []) + out

    def mass_of(self, name: str) -> str:
        return "MD" if name == "DC" else f"M{name[1:]}"


def link_force(link: Link) -> str:
    return f"FR{link.number}"


# -- the generator ----------------------------------------------------------------------------

TAIT_BRYAN = ["123", "132", "213", "231", "312", "321"]
PROPER_EULER = ["121", "131", "212", "232", "313", "323"]


class Generator:
    """Draws one description of a family from `rng`."""

    def __init__(self, family: str, rng: random.Random):
        self.rng = rng
        self.d = Description(family)

    # -- constants, coordinates, speeds -------------------------------------------------
    def constant(self, name: str, low: float, high: float, digits: int = 3) -> tuple:
        value = self.rng.uniform(low, high)
        self.d.constants[name] = f"{value:.{digits}f}"
        return ("c", name)

    def length(self, name: str) -> tuple:
        value = self.rng.uniform(0.3, 1.0) * self.rng.choice((-1, 1))
        self.d.constants[name] = f"{value:.3f}"
        return ("c", name)

    def coordinate(self, low=-1.0, high=1.0) -> int:
        self.d.nq += 1
        self.d.ranges[f"Q{self.d.nq}"] = (low, high)
        return self.d.nq

    def speed(self) -> int:
        self.d.nu += 1
        self.d.ranges[f"U{self.d.nu}"] = (-1.0, 1.0)
        return self.d.nu

    # -- links -------------------------------------------------------------------------------
    def offset(self, name: str, frame: str, axes) -> tuple:
        """A constant vector along some of `axes` of `frame`, one constant each."""
        chosen = [a for a in axes if self.rng.random() < 0.6] or [self.rng.choice(axes)]
        return tuple((self.length(f"{name}{XYZ[a - 1].upper()}"), frame, a) for a in chosen)

    def link(self, kind: str, parent: int, *, axes=(1, 2, 3), slides=(), rotation=None,
             velocity=None) -> Link:
        number = len(self.d.links) + 1 + (self.d.disc is not None)
        parent_frame = self.d.frame_of(parent)
        link = Link(number, kind, parent, offset=(),
                    velocity=velocity or self.rng.choice(("theory", "dt", "implied")))
        link.offset = self.offset(f"L{number}", parent_frame, axes) \
            if self.rng.random() < 0.8 or parent == 0 else ()
        link.slides = tuple((a, self.coordinate(), self.speed()) for a in slides)
        if rotation is not None:
            self.rotate(link, rotation)
        own = link.frame or parent_frame
        if rotation is not None and rotation.kind == "simprot" and kind == "particle":
            # a particle on its joint's axis would have no inertia about it
            link.mass_offset = self.off_axis(number, own, rotation.axis, axes)
        elif self.rng.random() < 0.85 or kind == "particle":
            link.mass_offset = self.offset(f"D{number}", own, axes)
        self.constant(f"M{number}", 0.5, 2.0)
        if kind == "body":
            link.inertia = self.inertia(number, planar=axes == (1, 2))
        self.d.links.append(link)
        return link

    def off_axis(self, number: int, frame: str, axis, axes) -> tuple:
        if isinstance(axis, int):
            others = [a for a in axes if a != abs(axis)]
            first = self.rng.choice(others)
            terms = [(self.length(f"D{number}{XYZ[first - 1].upper()}"), frame, first)]
            second = [a for a in others if a != first]
            if second and self.rng.random() < 0.5:
                a = second[0]
                terms.append((self.length(f"D{number}{XYZ[a - 1].upper()}"), frame, a))
            return tuple(terms)
        return tuple((self.length(f"D{number}{XYZ[a - 1].upper()}"), frame, a)
                     for a in (1, 2, 3))

    def inertia(self, number: int, planar: bool) -> tuple:
        names = [f"IXX{number}", f"IYY{number}", f"IZZ{number}"]
        for n in names:
            self.constant(n, 0.5, 1.5)
        if not planar and self.rng.random() < 0.4:
            literal = self.rng.random() < 0.5        # INERTIA B, IXX, IYY, IZZ, 0.05, 0, 0
            for n in (f"IXY{number}", f"IYZ{number}", f"IZX{number}"):
                if literal:
                    names.append(f"{self.rng.uniform(-0.1, 0.1):.3f}")
                else:
                    self.constant(n, -0.1, 0.1)
                    names.append(n)
        return tuple(names)

    def rotate(self, link: Link, rotation: Rotation) -> None:
        if rotation.kind == "simprot":
            rotation.q, rotation.u = (self.coordinate(),), (self.speed(),)
        elif rotation.kind == "dircos":
            proper = rotation.sequence[-3] == rotation.sequence[-1]
            middle = (0.4, 1.4) if proper else (-1.0, 1.0)
            rotation.q = (self.coordinate(), self.coordinate(*middle), self.coordinate())
            rotation.u = tuple(self.speed() for _ in range(3))
        else:
            rotation.q = tuple(self.coordinate() for _ in range(4))
            self.d.quaternions.append([f"Q{k}" for k in rotation.q])
            rotation.u = tuple(self.speed() for _ in range(3))
        link.rotation = rotation

    def simprot(self, vectors: bool = True) -> Rotation:
        speeds = self.rng.choice(("qdot", "w"))
        if vectors and self.rng.random() < 0.35:
            coefficients = [self.rng.choice((-2, -1, 1, 2, 3)) for _ in range(3)]
            # a vector of the parent: its unit vectors' names are filled in by the caller
            return Rotation("simprot", axis=tuple(coefficients), speeds=speeds)
        axis = self.rng.choice((1, 2, 3)) * self.rng.choice((1, -1))
        return Rotation("simprot", axis=axis, speeds=speeds)

    def dircos(self, kindiffs: bool) -> Rotation:
        sequence = self.rng.choice(("BODY", "SPACE")) + self.rng.choice(TAIT_BRYAN
                                                                          + PROPER_EULER)
        speeds = self.rng.choice(("child", "parent")) if kindiffs else "qdot"
        return Rotation("dircos", sequence=sequence, speeds=speeds)

    # -- loads --------------------------------------------------------------------------
    def points(self) -> list:
        out = ["NO"] + [p for link in self.d.links for p in (link.joint, link.mass_point)]
        return out + (["DCO"] if self.d.disc else [])

    def all_frames(self) -> list:
        return ["N"] + [link.frame for link in self.d.links if link.frame] + \
            (["DA", "DB", "DC"] if self.d.disc else [])

    def factor(self) -> tuple | None:
        nq, nu, rng = self.d.nq, self.d.nu, self.rng
        choice = rng.randrange(7)
        if choice == 0 or not nq:
            return None
        q, u = ("q", rng.randint(1, nq)), ("u", rng.randint(1, nu))
        return [None, ("sin", q), ("cos", q), u, ("t",), ("cos", ("t",)), ("*", q, u)][choice]

    def load_vector(self, name: str, frames: list, axes) -> tuple:
        terms = []
        for k in range(self.rng.randint(1, 2)):
            coefficient = self.constant(f"{name}{'AB'[k]}", -2.0, 2.0)
            factor = self.factor()
            scalar = coefficient if factor is None else ("*", coefficient, factor)
            terms.append((scalar, self.rng.choice(frames), self.rng.choice(axes)))
        return tuple(terms)

    def loads(self, planar: bool, count: int) -> None:
        axes = (1, 2) if planar else (1, 2, 3)
        turn_axes = (3,) if planar else (1, 2, 3)
        frames = self.all_frames()
        turning = frames[1:]
        points = self.points()
        for k in range(1, count + 1):
            kind = self.rng.choice(("force", "force_pair", "torque", "torque_pair", "spring"))
            if kind in ("torque", "torque_pair") and not turning:
                kind = "spring"
            if kind == "force":
                self.d.loads.append(Load(kind, (self.rng.choice(points[1:]),),
                                         self.load_vector(f"FF{k}", frames, axes)))
            elif kind == "force_pair":
                on = tuple(self.rng.sample(points, 2))
                self.d.loads.append(Load(kind, on, self.load_vector(f"FP{k}", frames, axes)))
            elif kind == "torque":
                self.d.loads.append(Load(kind, (self.rng.choice(turning),),
                                         self.load_vector(f"TT{k}", frames, turn_axes)))
            elif kind == "torque_pair":
                on = (self.rng.choice(frames), self.rng.choice(turning))
                if on[0] == on[1]:
                    on = ("N", on[1])
                self.d.loads.append(Load(kind, on,
                                         self.load_vector(f"TP{k}", frames, turn_axes)))
            else:
                first = self.anchor(k, planar) if self.rng.random() < 0.4 else \
                    self.rng.choice(points)
                if points[1:] == [first]:
                    first = "NO"        # a disc alone: its centre to the origin
                second = self.rng.choice([p for p in points[1:] if p != first])
                constants = (self.constant(f"KS{k}", 1.0, 5.0)[1],
                             self.constant(f"LS{k}", 0.1, 0.5)[1],
                             self.constant(f"CS{k}", 0.1, 0.5)[1])
                self.d.loads.append(Load(kind, (first, second), (), constants))

    def anchor(self, k: int, planar: bool) -> str:
        name = f"S{k}"
        self.d.anchors[name] = self.offset(f"S{k}", "N", (1, 2) if planar else (1, 2, 3))
        return name

    def gravity(self, planar: bool) -> None:
        if self.rng.random() < 0.15:
            return
        self.constant("G", 9.0, 10.0, digits=2)
        axis = self.rng.choice((1, 2) if planar else (1, 2, 3))
        terms = [(self.rng.choice((("c", "G"), ("neg", ("c", "G")))), "N", axis)]
        if not planar and self.rng.random() < 0.3:
            other = self.rng.choice([a for a in (1, 2, 3) if a != axis])
            terms.append((("*", ("n", "0.5"), ("c", "G")), "N", other))
        self.d.gravity = tuple(terms)

    # -- the tree ---------------------------------------------------------------------------
    def parent(self, chain: bool) -> int:
        numbers = [0] + [link.number for link in self.d.links]
        if self.d.disc is not None:
            numbers = [1] + numbers[1:]
        return numbers[-1] if chain else self.rng.choice(numbers)

    def tree(self, count: int, planar: bool, rotations: str = "simprot",
             chain: bool | None = None, velocity: str | None = None) -> None:
        chain = self.rng.random() < 0.5 if chain is None else chain
        axes = (1, 2) if planar else (1, 2, 3)
        for _ in range(count):
            parent = self.parent(chain)
            kind = self.rng.choice(("body", "particle"))
            slides = ()
            if self.rng.random() < 0.2:
                slides = (self.rng.choice(axes),)
            rotation = None
            # two three-angle joints at most: sympy's equations of three grow to
            # tens of millions of operations (minutes to form)
            turning = sum(1 for x in self.d.links if x.rotation and x.rotation.kind != "simprot")
            if rotations in ("dircos", "kindiffs") and turning < 2 and self.rng.random() < 0.7:
                kind = "body"
                rotation = self.dircos(kindiffs=rotations == "kindiffs")
                if rotations == "kindiffs" and self.rng.random() < 0.3:
                    rotation = Rotation("euler", speeds=self.rng.choice(("child", "parent")))
            elif planar:
                rotation = Rotation("simprot", axis=self.rng.choice((3, -3)),
                                    speeds=self.rng.choice(("qdot", "w")))
            elif kind == "body" or self.rng.random() < 0.8:
                rotation = self.simprot()
            if rotation is None and not slides:
                slides = (self.rng.choice(axes),)
            if rotation is not None and isinstance(rotation.axis, tuple) \
                    and rotation.kind == "simprot":
                frame = self.d.frame_of(parent)
                rotation.axis = tuple((("n", str(c)), frame, a + 1)
                                      for a, c in enumerate(rotation.axis))
            self.link(kind, parent, axes=axes, slides=slides, rotation=rotation,
                      velocity=velocity)

    # -- constraints --------------------------------------------------------------------
    def speeds_moving(self, number: int) -> list:
        """The speeds a point of link `number` moves with (its own and its ancestors')."""
        out = []
        while number:
            if self.d.disc is not None and number == 1:
                return out + [1, 2, 3]      # the disc's own speeds besides the contact's
            link = self.d.link(number)
            out += [s[2] for s in link.slides]
            if link.rotation is not None:
                out += list(link.rotation.u)
            number = link.parent
        return out

    def moving(self, link: Link) -> dict:
        """{point: the speeds it moves with} of the link's joint and mass point."""
        joint = self.speeds_moving(link.parent) + [s[2] for s in link.slides]
        turning = list(link.rotation.u) if link.rotation and link.mass_offset else []
        return {link.joint: joint, link.mass_point: joint + turning}

    def moved_along(self, speed: int, axes) -> list:
        """The axes of N a speed can move a point along: a slide in N along its own, a
        turn about an axis of N across it (any axis for the rest)."""
        for link in self.d.links:
            if self.d.frame_of(link.parent) != "N":
                continue
            for axis, _, u in link.slides:
                if u == speed:
                    return [axis]
            rot = link.rotation
            if rot and rot.kind == "simprot" and isinstance(rot.axis, int) \
                    and rot.u == (speed,):
                return [a for a in axes if a != abs(rot.axis)]
        return list(axes)

    def motion_constraints(self, kind: str, count: int, fixed_direction: bool,
                           axes=(1, 2, 3), links=None, written=None) -> None:
        taken = {s[3] for s in self.d.aux_slides}      # already auxiliary
        for k in range(1, count + 1):
            if len(taken) + 1 >= self.d.nu:
                return                  # one speed at least stays independent
            choices = [(p, u) for link in (links or self.d.links)
                       for p, speeds in self.moving(link).items()
                       for u in speeds if u not in taken]
            if not choices:
                return
            point, speed = self.rng.choice(choices)
            taken.add(speed)
            link = next(x for x in self.d.links if point in (x.joint, x.mass_point))
            if fixed_direction:
                direction = ((None, "N", self.rng.choice(self.moved_along(speed, axes))),)
                if self.rng.random() < 0.3:
                    direction += ((("n", str(self.rng.choice((-2, 2, 3)))), "N",
                                   self.rng.choice(axes)),)
                written = written or self.rng.choice(("velocity", "dt"))
            else:
                frame = link.frame or self.d.frame_of(link.parent)
                direction = ((None, frame, self.rng.choice((1, 2))),)
                written = "velocity"
            force = f"FC{k}" if kind == "auxiliary" else None
            self.d.constraints.append(Constraint(kind, point, direction, speed, written, force))


# -- the families --------------------------------------------------------------------------

def planar(g: Generator) -> None:
    """Chains and trees of 1-4 bodies and particles in the plane of N1>, N2>."""
    g.tree(g.rng.randint(1, 4), planar=True)
    g.gravity(planar=True)
    g.loads(planar=True, count=g.rng.randint(0, 3))


def spatial(g: Generator) -> None:
    """Trees of 1-4 links in space: SIMPROT about +-1, +-2, +-3 or a vector, slides."""
    g.tree(g.rng.randint(1, 4), planar=False)
    g.gravity(planar=False)
    g.loads(planar=False, count=g.rng.randint(0, 3))


def dircos(g: Generator) -> None:
    """DIRCOS(A, B, BODYijk | SPACEijk, ...) with q' = u, W implied."""
    g.tree(g.rng.randint(1, 3), planar=False, rotations="dircos")
    g.gravity(planar=False)
    g.loads(planar=False, count=g.rng.randint(0, 2))


def kindiffs(g: Generator) -> None:
    """DIRCOS with KINDIFFS: the speeds are W's measure numbers in the child's or the
    parent's frame; Euler parameters (DIRCOS/KINDIFFS EULER) too."""
    g.tree(g.rng.randint(1, 3), planar=False, rotations="kindiffs")
    g.gravity(planar=False)
    g.loads(planar=False, count=g.rng.randint(0, 2))


def holonomic(g: Generator) -> None:
    """A point's velocity along a direction fixed in N is zero (a differentiated
    holonomic constraint): DEPENDENT[...] and CONSTRAIN(DEPENDENT[...]), one or two."""
    is_planar = g.rng.random() < 0.5
    g.tree(g.rng.randint(2, 4), planar=is_planar)
    g.motion_constraints("dependent", g.rng.randint(1, 2), fixed_direction=True,
                         axes=(1, 2) if is_planar else (1, 2, 3))
    g.gravity(planar=is_planar)
    g.loads(planar=is_planar, count=g.rng.randint(0, 2))


def knife_edge(g: Generator) -> None:
    """A point's velocity along a direction fixed in its link is zero (nonholonomic):
    a sleigh sliding and turning in the plane, with links on it."""
    sleigh = g.link("body", 0, axes=(1, 2), slides=(1, 2),
                    rotation=Rotation("simprot", axis=3, speeds=g.rng.choice(("qdot", "w"))))
    g.tree(g.rng.randint(0, 2), planar=True)
    g.motion_constraints("dependent", 1, fixed_direction=False, links=[sleigh])
    g.gravity(planar=True)
    g.loads(planar=True, count=g.rng.randint(0, 2))


def rolling_disc(g: Generator) -> None:
    """A disc rolling without slip on N's plane (contact speeds U4, U5 dependent),
    carrying 0-2 links."""
    g.d.disc = Disc(speeds=g.rng.choice(("qdot", "w")))
    for _ in range(5):
        g.coordinate()
        g.speed()
    g.d.ranges["Q2"] = (-0.8, 0.8)                  # the lean
    g.constant("RD", 0.3, 0.8)
    g.constant("MD", 0.5, 2.0)
    for n in ("IDX", "IDY", "IDZ"):
        g.constant(n, 0.5, 1.5)
    for k, direction in ((4, 1), (5, 2)):
        g.d.constraints.append(Constraint("dependent", "DN", ((None, "N", direction),), k))
    g.tree(g.rng.randint(0, 2), planar=False, chain=False)
    g.constant("G", 9.0, 10.0, digits=2)
    g.d.gravity = ((("neg", ("c", "G")), "N", 3),)
    g.loads(planar=False, count=g.rng.randint(0, 2))


def aux_reaction(g: Generator) -> None:
    """Auxiliary speeds zero in the motion, bringing joint reactions into evidence:
    a joint's slack speed UA (AUXILIARY[k] = UAk) with the reaction between its two
    sides, or a root's slides whose speeds are auxiliary (AUXILIARY[k] = Uk, Q fixed)
    with the force holding it; KANE(F, ...) solves for them.  Now and then a DEPENDENT
    constraint too, whose point may move with a slack speed (the fourbar's pattern)."""
    count = g.rng.randint(1, 3)
    if g.rng.random() < 0.4:
        axes = tuple(g.rng.sample((1, 2, 3), g.rng.randint(1, 2)))
        root = g.link("body", 0, slides=axes, rotation=g.simprot(vectors=False),
                      velocity="theory")
        for axis, q, u in root.slides:
            g.d.aux_slides.append((root.number, axis, q, u, f"FS{u}"))
        g.tree(count - 1, planar=False, velocity="theory")
    else:
        g.tree(count, planar=False, velocity="theory")
        for link in g.rng.sample(g.d.links, g.rng.randint(1, min(2, count))):
            g.d.naux += 1
            frame = g.rng.choice(("N", g.d.frame_of(link.parent)))
            link.aux = (g.d.naux, ((None, frame, g.rng.choice((1, 2, 3))),))
    if count > 1 and g.rng.random() < 0.35:
        # through the velocity, which has the slack speeds (a position's DT has not)
        g.motion_constraints("dependent", 1, fixed_direction=True, written="velocity")
    g.gravity(planar=False)
    g.loads(planar=False, count=g.rng.randint(0, 2))


def aux_constraint(g: Generator) -> None:
    """A point's velocity along a direction fixed in N is zero, written as an auxiliary
    constraint, CONSTRAIN(AUXILIARY[U]), with the constraint force along it as KANE's
    unknown: Autolev solves the constraint for U, which then follows the others."""
    is_planar = g.rng.random() < 0.5
    g.tree(g.rng.randint(2, 3), planar=is_planar)
    g.motion_constraints("auxiliary", 1, fixed_direction=True,
                         axes=(1, 2) if is_planar else (1, 2, 3))
    g.d.multipliers = True
    g.gravity(planar=is_planar)
    g.loads(planar=is_planar, count=g.rng.randint(0, 2))


FAMILIES = {f.__name__: f for f in (planar, spatial, dircos, kindiffs, holonomic,
                                     knife_edge, rolling_disc, aux_reaction,
                                     aux_constraint)}


def generate(family: str, rng: random.Random) -> Description:
    g = Generator(family, rng)
    FAMILIES[family](g)
    return g.d


# -- Autolev text ------------------------------------------------------------------------------

def _names(prefix: str, numbers) -> str:
    return ", ".join(f"{prefix}{k}'" for k in numbers)


def autolev_text(d: Description, title: str) -> str:
    lines = [f"% {title}", "NEWTONIAN N"]
    if d.bodies():
        lines.append("BODIES " + ", ".join(d.bodies()))
    if d.frames():
        lines.append("FRAMES " + ", ".join(d.frames()))
    if d.particles():
        lines.append("PARTICLES " + ", ".join(d.particles()))
    points = [link.joint for link in d.links] + [link.aux_point for link in d.links if link.aux]
    points += list(d.anchors) + (["DN"] if d.disc else [])
    lines.append("POINTS " + ", ".join(points))
    motion = [_names("Q", range(1, d.nq + 1)), _names("U", range(1, d.nu + 1))]
    if d.naux:
        motion.append(_names("UA", range(1, d.naux + 1)))
    lines.append("MOTIONVARIABLES' " + ", ".join(motion))
    if d.unknowns():
        lines.append("VARIABLES " + ", ".join(d.unknowns()))
    lines.append("CONSTANTS " + ", ".join(d.constants))
    masses = [f"{b} = {d.mass_of(b)}" for b in d.bodies()]
    masses += [f"{p} = M{p[1:]}" for p in d.particles()]
    lines.append("MASS " + ", ".join(masses))
    if d.disc:
        lines.append("INERTIA DC, IDX, IDY, IDZ")
    for link in d.links:
        if link.kind == "body":
            lines.append(f"INERTIA {link.frame}, " + ", ".join(link.inertia))
    lines.append("V_NO_N> = 0>")
    if d.disc:
        lines += _disc_autolev(d.disc)
    for link in d.links:
        lines += _link_autolev(d, link)
    for name, terms in d.anchors.items():
        lines += [f"P_NO_{name}> = {autolev_vector(terms)}", f"V_{name}_N> = 0>"]
    lines += _constraints_autolev(d)
    lines += _loads_autolev(d)
    lines.append("ZERO = FR() + FRSTAR()")
    lines.append(f"KANE({', '.join(d.unknowns())})")
    lines += _inputs_autolev(d)
    outputs = ["T"] + d.unknowns()
    lines.append("OUTPUT " + ", ".join(outputs))
    lines.append("CODE DYNAMICS() case.c")
    return "\n".join(lines) + "\n"


def _disc_autolev(disc: Disc) -> list:
    lines = ["SIMPROT(N, DA, 3, Q1)", "SIMPROT(DA, DB, 1, Q2)", "SIMPROT(DB, DC, 2, Q3)"]
    lines += [f"Q{k}' = U{k}" for k in range(1, 6)]
    if disc.speeds == "w":
        lines += ["W_DA_N> = U1*N3>", "W_DB_DA> = U2*DA1>", "W_DC_DB> = U3*DB2>"]
    lines += ["P_NO_DCO> = Q4*N1> + Q5*N2> + RD*DB3>", "V_DCO_N> = DT(P_NO_DCO>, N)",
              "P_DCO_DN> = -RD*DB3>", "V2PTS(N, DC, DCO, DN)"]
    return lines


def _axis_autolev(parent: str, axis) -> str:
    if isinstance(axis, int):
        return str(axis)
    return autolev_vector(axis)


def _link_autolev(d: Description, link: Link) -> list:
    parent_frame, parent_point = d.frame_of(link.parent), d.point_of(link.parent)
    frame = link.frame or parent_frame
    lines = []
    rot = link.rotation
    if rot is not None:
        qs = ", ".join(f"Q{k}" for k in rot.q)
        if rot.kind == "simprot":
            lines.append(f"SIMPROT({parent_frame}, {frame}, "
                         f"{_axis_autolev(parent_frame, rot.axis)}, Q{rot.q[0]})")
        elif rot.kind == "dircos":
            lines.append(f"DIRCOS({parent_frame}, {frame}, {rot.sequence}, {qs})")
        else:
            lines.append(f"DIRCOS({parent_frame}, {frame}, EULER, {qs})")
        if rot.speeds in ("qdot", "w"):
            lines += [f"Q{q}' = U{u}" for q, u in zip(rot.q, rot.u)]
        if rot.speeds == "w":
            u = f"U{rot.u[0]}"
            if isinstance(rot.axis, int):
                sign = "-" if rot.axis < 0 else ""
                lines.append(f"W_{frame}_{parent_frame}> = {sign}{u}*{parent_frame}"
                             f"{abs(rot.axis)}>")
            else:
                lines.append(f"W_{frame}_{parent_frame}> = "
                             f"{u}*UNITVEC({autolev_vector(rot.axis)})")
        if rot.speeds in ("child", "parent"):
            basis = frame if rot.speeds == "child" else parent_frame
            w = " + ".join(f"U{u}*{basis}{i + 1}>" for i, u in enumerate(rot.u))
            lines.append(f"W_{frame}_{parent_frame}> = {w}")
            kind = rot.sequence if rot.kind == "dircos" else "EULER"
            lines.append(f"KINDIFFS({parent_frame}, {frame}, {kind}, {qs})")
    slide_terms = tuple((("q", q), parent_frame, axis) for axis, q, _ in link.slides)
    lines += [f"Q{q}' = U{u}" for _, q, u in link.slides]
    lines.append(f"P_{parent_point}_{link.joint}> = "
                 f"{autolev_vector(link.offset + slide_terms)}")
    base = link.joint
    if link.velocity == "theory":
        if link.slides:
            v = " + ".join(f"U{u}*{parent_frame}{axis}>" for axis, _, u in link.slides)
            if parent_frame == "N":     # V1PT's V_J_N> would be the one it computes
                lines.append(f"V_{link.joint}_N> = V_{parent_point}_N> + {v}")
            else:
                lines += [f"V_{link.joint}_{parent_frame}> = {v}",
                          f"V1PT(N, {parent_frame}, {parent_point}, {link.joint})"]
        else:
            lines.append(f"V2PTS(N, {parent_frame}, {parent_point}, {link.joint})")
    elif link.velocity == "dt":
        lines.append(f"V_{link.joint}_N> = DT(P_NO_{link.joint}>, N)")
    if link.aux:
        number, direction = link.aux
        base = link.aux_point
        lines += [f"P_{link.joint}_{base}> = 0>",
                  f"V_{base}_N> = V_{link.joint}_N> + UA{number}*{autolev_vector(direction)}"]
    lines.append(f"P_{base}_{link.mass_point}> = {autolev_vector(link.mass_offset)}")
    if link.velocity == "theory":
        lines.append(f"V2PTS(N, {frame}, {base}, {link.mass_point})")
    elif link.velocity == "dt":
        lines.append(f"V_{link.mass_point}_N> = DT(P_NO_{link.mass_point}>, N)")
    return lines


def _constraints_autolev(d: Description) -> list:
    lines = []
    groups = {"dependent": [], "auxiliary": []}
    for c in d.constraints:
        groups[c.kind].append(c)
    for kind, constraints in groups.items():
        array = kind.upper()
        for k, c in enumerate(constraints, 1):
            if c.written == "dt":
                lines.append(f"{array}[{k}] = DT(DOT(P_NO_{c.point}>, "
                             f"{autolev_vector(c.direction)}))")
            else:
                lines.append(f"{array}[{k}] = DOT(V_{c.point}_N>, "
                             f"{autolev_vector(c.direction)})")
    aux = [f"UA{link.aux[0]}" for link in d.links if link.aux]
    aux += [f"U{s[3]}" for s in d.aux_slides]
    for k, name in enumerate(aux, len(groups["auxiliary"]) + 1):
        lines.append(f"AUXILIARY[{k}] = {name}")
    if groups["dependent"]:
        speeds = ", ".join(f"U{c.speed}" for c in groups["dependent"])
        lines.append(f"CONSTRAIN(DEPENDENT[{speeds}])")
    if groups["auxiliary"] or aux:
        speeds = [f"U{c.speed}" for c in groups["auxiliary"]] + aux
        lines.append(f"CONSTRAIN(AUXILIARY[{', '.join(speeds)}])")
    return lines


def _loads_autolev(d: Description) -> list:
    lines = []
    if d.gravity:
        lines.append(f"GRAVITY({autolev_vector(d.gravity)})")
    for load in d.loads:
        v = autolev_vector(load.vector)
        if load.kind == "force":
            lines.append(f"FORCE({load.on[0]}, {v})")
        elif load.kind == "force_pair":
            lines.append(f"FORCE({load.on[0]}/{load.on[1]}, {v})")
        elif load.kind == "torque":
            lines.append(f"TORQUE({load.on[0]}, {v})")
        elif load.kind == "torque_pair":
            lines.append(f"TORQUE({load.on[0]}/{load.on[1]}, {v})")
        else:
            a, b = load.on
            k, length, c = load.constants
            r = f"P_{a}_{b}>"
            lines.append(f"FORCE({a}/{b}, -({k}*(MAG({r}) - {length}) + {c}*DOT(V_{b}_N> - "
                         f"V_{a}_N>, UNITVEC({r})))*UNITVEC({r}))")
    for link in d.links:
        if link.aux:
            direction = autolev_vector(link.aux[1])
            lines.append(f"FORCE({link.joint}/{link.aux_point}, {link_force(link)}*"
                         f"({direction}))")
    for number, axis, _, _, force in d.aux_slides:
        lines.append(f"FORCE(J{number}, {force}*N{axis}>)")
    for c in d.constraints:
        if c.force:
            lines.append(f"FORCE({c.point}, {c.force}*({autolev_vector(c.direction)}))")
    return lines


def initial_values(d: Description) -> dict:
    """The INPUT value of each coordinate and independent speed: the middle of its range
    (Euler parameters: no turn)."""
    values = {}
    for name, (low, high) in d.ranges.items():
        values[name] = f"{(low + high) / 2 + 0.1:.3f}"
    for names in d.quaternions:
        values.update(zip(names, ("0", "0", "0", "1")))
    not_inputs = set(d.dependent_speeds()) | set(d.auxiliary_speeds())
    return {k: v for k, v in values.items() if k not in not_inputs}


def _inputs_autolev(d: Description) -> list:
    lines = []
    items = [f"{k} = {v}" for k, v in d.constants.items()]
    items += [f"{k} = {v}" for k, v in initial_values(d).items()]
    for start in range(0, len(items), 6):
        lines.append("INPUT " + ", ".join(items[start:start + 6]))
    lines.append("INPUT TFINAL = 1, INTEGSTP = 0.1")
    return lines


# -- the sympy script ---------------------------------------------------------------------------

def sympy_script(d: Description, title: str) -> str:
    """A script that builds the description with sympy.physics.mechanics alone and leaves,
    as module names: kane (its KanesMethod, equations formed), coordinates, speeds,
    dependent, auxiliary, unknowns, velocity_constraints (in the speeds), names
    ({dynamicsymbol: Autolev name}), constants ({symbol: value}) and guards
    (expressions that must stay away from zero: spring lengths)."""
    w = _ScriptWriter(d)
    return w.write(title)


class _ScriptWriter:
    def __init__(self, d: Description):
        self.d = d
        self.lines: list = []
        self.anchor_of: dict = {"NO": "NO"}    # each point's nearest auxiliary point above

    def emit(self, *lines) -> None:
        self.lines.extend(lines)

    def write(self, title: str) -> str:
        d = self.d
        aux_slide_speeds = {s[3] for s in d.aux_slides}
        constrained = {c.speed for c in d.constraints}
        qs = [f"q{k}" for k in range(1, d.nq + 1)]
        us = [f"u{k}" for k in range(1, d.nu + 1)]
        uas = [f"ua{k}" for k in range(1, d.naux + 1)]
        self.emit(f'"""{title}: the sympy.physics.mechanics side, built directly."""',
                  "import sympy as sm", "import sympy.physics.mechanics as me", "",
                  "t = me.dynamicsymbols._t")
        for group in (qs, us, uas, d.unknowns()):
            if group:
                self.emit(f"{', '.join(group)}, = me.dynamicsymbols('{', '.join(group)},')")
        names = list(d.constants)
        self.emit(f"{', '.join(names)}, = sm.symbols('{', '.join(names)},', real=True)")
        self.emit("constants = {" + ", ".join(f"{k}: {v}" for k, v in d.constants.items())
                  + "}")
        self.emit("names = {" + ", ".join(
            [f"{q}: '{q.upper()}'" for q in qs] + [f"{u}: '{u.upper()}'" for u in us]
            + [f"{u}: '{u.upper()}'" for u in uas]
            + [f"{f}: '{f}'" for f in d.unknowns()]) + "}")
        self.emit("", "N = me.ReferenceFrame('N')", "NO = me.Point('NO')", "NO.set_vel(N, 0)",
                  "kd_eqs = []", "bodies = []", "loads = []", "guards = []")
        if d.disc:
            self.disc()
        for link in d.links:
            self.link(link)
        for name, terms in d.anchors.items():
            self.emit(f"{name} = NO.locatenew('{name}', {sympy_vector(terms)})",
                      f"{name}.set_vel(N, 0)")
        self.velocities()
        self.loads()
        independent = [u for k, u in enumerate(us, 1)
                       if k not in constrained and k not in aux_slide_speeds]
        dependent = [f"u{c.speed}" for c in d.constraints]
        auxiliary = uas + [f"u{k}" for k in sorted(aux_slide_speeds)]
        self.emit("", "coordinates = [" + ", ".join(qs) + "]",
                  "speeds = [" + ", ".join(independent) + "]",
                  "dependent = [" + ", ".join(dependent) + "]",
                  "auxiliary = [" + ", ".join(auxiliary) + "]",
                  "unknowns = [" + ", ".join(d.unknowns()) + "]")
        self.constraints()
        self.emit("kane = me.KanesMethod(N, coordinates, speeds, kd_eqs=kd_eqs,",
                  "                      u_dependent=dependent or None,",
                  "                      velocity_constraints=velocity_constraints or None,",
                  "                      u_auxiliary=auxiliary or None)",
                  "fr, frstar = kane.kanes_equations(bodies, loads)")
        if d.multipliers:
            self.emit("# the constraint forces: the equations of the unconstrained system,",
                      "# M u' = f + J^T F, hold at the constrained motion's u'",
                      "free = me.KanesMethod(N, coordinates, speeds + dependent, "
                      "kd_eqs=kd_eqs)",
                      "free.kanes_equations(bodies, loads)")
        return "\n".join(self.lines) + "\n"

    def disc(self) -> None:
        disc = self.d.disc
        self.emit("# the rolling disc: yaw DA, lean DB, spin DC",
                  "DA = me.ReferenceFrame('DA')", "DA.orient_axis(N, N.z, q1)",
                  "DB = me.ReferenceFrame('DB')", "DB.orient_axis(DA, DA.x, q2)",
                  "DC = me.ReferenceFrame('DC')", "DC.orient_axis(DB, DB.y, q3)")
        self.emit(*[f"kd_eqs.append(q{k}.diff(t) - u{k})" for k in range(1, 6)])
        if disc.speeds == "w":
            self.emit("DA.set_ang_vel(N, u1*N.z)", "DB.set_ang_vel(DA, u2*DA.x)",
                      "DC.set_ang_vel(DB, u3*DB.y)")
        self.emit("DCO = NO.locatenew('DCO', q4*N.x + q5*N.y + RD*DB.z)",
                  "DN = DCO.locatenew('DN', -RD*DB.z)",
                  "bodies.append(me.RigidBody('DC', DCO, DC, MD, "
                  "(me.inertia(DC, IDX, IDY, IDZ), DCO)))")
        self.anchor_of["DCO"] = "NO"

    def link(self, link: Link) -> None:
        d = self.d
        parent_frame, parent_point = d.frame_of(link.parent), d.point_of(link.parent)
        frame = link.frame or parent_frame
        self.emit(f"# link {link.number}: {link.kind} {link.mass_point}")
        rot = link.rotation
        if rot is not None:
            self.emit(f"{frame} = me.ReferenceFrame('{frame}')")
            qs = [f"q{k}" for k in rot.q]
            if rot.kind == "simprot":
                if isinstance(rot.axis, int):
                    unit = f"{parent_frame}.{XYZ[abs(rot.axis) - 1]}"
                    axis = f"-{unit}" if rot.axis < 0 else unit
                else:
                    axis = f"({sympy_vector(rot.axis)}).normalize()"
                self.emit(f"{frame}.orient_axis({parent_frame}, {axis}, {qs[0]})")
            elif rot.kind == "dircos":
                method = "orient_body_fixed" if rot.sequence.startswith("BODY") \
                    else "orient_space_fixed"
                self.emit(f"{frame}.{method}({parent_frame}, ({', '.join(qs)}), "
                          f"'{rot.sequence[-3:]}')")
            else:
                # Autolev's E4 is the scalar part
                self.emit(f"{frame}.orient_quaternion({parent_frame}, "
                          f"({qs[3]}, {qs[0]}, {qs[1]}, {qs[2]}))")
            if rot.speeds in ("qdot", "w"):
                self.emit(*[f"kd_eqs.append(q{q}.diff(t) - u{u})"
                            for q, u in zip(rot.q, rot.u)])
            if rot.speeds == "w":
                self.emit(f"{frame}.set_ang_vel({parent_frame}, u{rot.u[0]}*{axis})")
            if rot.speeds in ("child", "parent"):
                basis = frame if rot.speeds == "child" else parent_frame
                w = " + ".join(f"u{u}*{basis}.{XYZ[i]}" for i, u in enumerate(rot.u))
                self.emit(f"implied = {frame}.ang_vel_in({parent_frame})",
                          f"{frame}.set_ang_vel({parent_frame}, {w})",
                          f"difference = implied - {frame}.ang_vel_in({parent_frame})",
                          "kd_eqs += [" + ", ".join(f"difference.dot({frame}.{a})"
                                                    for a in XYZ) + "]")
                if rot.kind == "euler":
                    # four parameters, three speeds: the parameters stay of unit length
                    self.emit("kd_eqs.append(" + " + ".join(f"{q}*{q}.diff(t)" for q in qs)
                              + ")")
        slide_terms = tuple((("q", q), parent_frame, axis) for axis, q, _ in link.slides)
        self.emit(*[f"kd_eqs.append(q{q}.diff(t) - u{u})" for _, q, u in link.slides])
        self.emit(f"{link.joint} = {parent_point}.locatenew('{link.joint}', "
                  f"{sympy_vector(link.offset + slide_terms)})")
        self.anchor_of[link.joint] = self.anchor_of[parent_point]
        base = link.joint
        if link.aux:
            number, direction = link.aux
            base = link.aux_point
            self.emit(f"{base} = {link.joint}.locatenew('{base}', 0)")
            self.anchor_of[base] = base
        self.emit(f"{link.mass_point} = {base}.locatenew('{link.mass_point}', "
                  f"{sympy_vector(link.mass_offset)})")
        self.anchor_of[link.mass_point] = self.anchor_of[base]
        mass = f"M{link.number}"
        if link.kind == "body":
            self.emit(f"bodies.append(me.RigidBody('{frame}', {link.mass_point}, {frame}, "
                      f"{mass}, (me.inertia({frame}, {', '.join(link.inertia)}), "
                      f"{link.mass_point})))")
        else:
            self.emit(f"bodies.append(me.Particle('{link.mass_point}', {link.mass_point}, "
                      f"{mass}))")

    def velocities(self) -> None:
        """Each point's velocity in N: the derivative in N of its position from its
        nearest auxiliary point above (else NO), plus that point's velocity."""
        d = self.d
        self.emit("# velocities: positions differentiated in N")
        for link in d.links:
            points = [link.joint] + ([link.aux_point] if link.aux else []) + [link.mass_point]
            for p in points:
                anchor = self.anchor_of[p]
                if p == anchor:
                    number, direction = link.aux
                    self.emit(f"{p}.set_vel(N, {link.joint}.vel(N) + "
                              f"ua{number}*({sympy_vector(direction)}))")
                else:
                    self.emit(f"{p}.set_vel(N, {anchor}.vel(N) + "
                              f"{p}.pos_from({anchor}).dt(N))")
        if d.disc:
            self.emit("DCO.set_vel(N, DCO.pos_from(NO).dt(N))",
                      "DN.v2pt_theory(DCO, N, DC)")

    def loads(self) -> None:
        d = self.d
        self.emit("# loads")
        if d.gravity:
            self.emit(f"gravity = {sympy_vector(d.gravity)}",
                      "loads += [(b.masscenter, b.mass*gravity) if isinstance(b, me.RigidBody)"
                      " else (b.point, b.mass*gravity) for b in bodies]")
        for k, load in enumerate(d.loads, 1):
            v = sympy_vector(load.vector)
            if load.kind == "force":
                self.emit(f"loads.append(({load.on[0]}, {v}))")
            elif load.kind in ("force_pair", "torque_pair"):
                a, b = load.on
                self.emit(f"loads += [({b}, {v}), ({a}, -({v}))]")
            elif load.kind == "torque":
                self.emit(f"loads.append(({load.on[0]}, {v}))")
            else:
                a, b = load.on
                stiffness, length, damping = load.constants
                self.emit(f"r{k} = {b}.pos_from({a})",
                          f"along{k} = r{k}/r{k}.magnitude()",
                          f"tension{k} = {stiffness}*(r{k}.magnitude() - {length}) + "
                          f"{damping}*({b}.vel(N) - {a}.vel(N)).dot(along{k})",
                          f"loads += [({b}, -tension{k}*along{k}), ({a}, tension{k}*along{k})]",
                          f"guards.append(r{k}.magnitude())")
        for link in d.links:
            if link.aux:
                v = sympy_vector(link.aux[1])
                force = link_force(link)
                self.emit(f"loads += [({link.aux_point}, {force}*({v})), "
                          f"({link.joint}, -{force}*({v}))]")
        for number, axis, _, _, force in d.aux_slides:
            self.emit(f"loads.append((J{number}, {force}*N.{XYZ[axis - 1]}))")
        for c in d.constraints:
            if c.force:
                self.emit(f"loads.append(({c.point}, {c.force}*({sympy_vector(c.direction)})))")

    def constraints(self) -> None:
        """The velocity constraints in the speeds: q' replaced through kd_eqs."""
        d = self.d
        self.emit("rates = me.KanesMethod(N, coordinates, speeds + dependent + auxiliary, "
                  "kd_eqs=kd_eqs).kindiffdict()")
        rows = []
        for c in d.constraints:
            rows.append(f"me.msubs({c.point}.vel(N).dot({sympy_vector(c.direction)}), rates)")
        self.emit("velocity_constraints = [" + ", ".join(rows) + "]")
