"""Plain sympy objects from a model: expressions in dynamicsymbols, sympy.physics.vector
frames and vectors, and sympy.physics.mechanics.SymbolicSystem forms.

The engine keeps time-varying quantities as Symbols (Q1, Q1') and intermediate Z's;
here every Z and definition is expanded and each variable becomes the function of
time sympy.physics.mechanics expects (q1(t), with q1(t).diff(t) for Q1').
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import sympy as sm

from . import symbols as S
from ..engine.errors import AutolevModelError

if TYPE_CHECKING:
    from .frame import Frame, Scene
    from .vectors import Vector


def _mechanics():
    # sympy.physics.mechanics takes 0.1 s to import: only sympy interop pays it
    import sympy.physics.mechanics
    return sympy.physics.mechanics


def dynamic_map(scene: "Scene") -> dict:
    """{our symbol: its sympy counterpart}: every variable and derivative a dynamicsymbol,
    every constant a plain Symbol of its name (no assumptions: `sm.Symbol('K')` written
    by a SymPy user is the model's K).  The one convention of everything handed to
    sympy: to_sympy, symbolic_system, to_mechanics and the SymPy scripts."""
    me = _mechanics()
    mapping: dict = {S.TIME: me.dynamicsymbols._t}
    for sym, info in scene.info.items():
        base, order = S.base_and_order(sym)
        if info.kind == "constant":
            mapping[sym] = sm.Symbol(sym.name)
            continue
        if order:
            continue
        f = me.dynamicsymbols(sym.name)
        mapping[sym] = f
        for k in range(1, info.order + 3):
            mapping[S.derivative(sym, k)] = f.diff(me.dynamicsymbols._t, k)
    return mapping


def to_sympy_expr(scene: "Scene", expr, mapping: dict | None = None, keep=frozenset()):
    """The expression (or matrix) with every definition expanded but those of the symbols
    in `keep` (the hand-off's dependent speeds), in dynamicsymbols."""
    mapping = mapping if mapping is not None else dynamic_map(scene)
    done: dict = {}
    if isinstance(expr, sm.MatrixBase):
        return expr.applyfunc(lambda e: _replaced(scene.defs.explicit(e, keep), mapping, done))
    return _replaced(scene.defs.explicit(expr, keep), mapping, done)


def _replaced(expr, mapping: dict, done: dict):
    """`expr.xreplace(mapping)` once per distinct subexpression: an expanded model shares
    its subexpressions (the Whipple's forcing: 2 255 of them, a tree too large to walk)."""
    found = done.get(expr)
    if found is not None:
        return found
    if expr in mapping:
        found = mapping[expr]
    elif not expr.args:
        found = expr
    else:
        args = [_replaced(a, mapping, done) for a in expr.args]
        found = expr.func(*args) if any(a is not b for a, b in zip(args, expr.args)) else expr
    done[expr] = found
    return found


# the two axes a rotation about axis k turns, in right-handed order
_TURNED = {0: (1, 2), 1: (2, 0), 2: (0, 1)}


def simple_rotation(dcm) -> tuple[int, object] | None:
    """(axis 0-2, angle) when parent.dcm(child) `dcm` turns the parent about one of its
    axes (SIMPROT's matrices), else None."""
    for k, (i, j) in _TURNED.items():
        others = [(r, c) for r in range(3) for c in range(3) if (r == k) != (c == k)]
        if dcm[k, k] != 1 or any(dcm[r, c] != 0 for r, c in others):
            continue
        cosine = dcm[i, i]
        if not isinstance(cosine, sm.cos):
            continue
        angle = cosine.args[0]
        for turned in (angle, -angle):
            expected = [[sm.cos(turned), -sm.sin(turned)], [sm.sin(turned), sm.cos(turned)]]
            if all(sm.expand(dcm[a, b] - expected[x][y]) == 0
                   for x, a in enumerate((i, j)) for y, b in enumerate((i, j))):
                return k, turned
    return None


def to_sympy_frame(frame: "Frame", mapping: dict | None = None, cache: dict | None = None,
                   orientations: list | None = None, keep=frozenset()):
    """A sympy ReferenceFrame oriented as `frame` is (through the model's frames).
    `mapping` and `cache` ({Frame: ReferenceFrame}): a translation of the symbols of
    one's own, with the frames it makes (default: the model's, kept with it);
    `orientations` receives each (parent, child, parent.dcm(child), angular velocity of
    the child in the parent or None) in the order the frames are made; `keep`: symbols
    whose definitions are not expanded."""
    me = _mechanics()
    scene = frame.scene
    if cache is None:
        cache = scene.derived.table("sympy frames")
    if frame in cache:
        return cache[frame]
    mapping = mapping if mapping is not None else dynamic_map(scene)
    # orient every frame reachable from this one along a spanning tree of the edges
    root = frame
    todo = [root]
    cache[root] = me.ReferenceFrame(root.name)
    while todo:
        f = todo.pop()
        for g in f.oriented_neighbours():
            if g in cache or g.name == "_probe":
                continue
            sg = me.ReferenceFrame(g.name)
            dcm = to_sympy_expr(scene, f.dcm(g), mapping, keep)     # f_i . g_j
            rotation = simple_rotation(dcm)
            # orient_explicit differentiates the matrix and trigsimps it: minutes on a
            # bicycle's frames, which SIMPROT turns about one axis each
            if rotation is not None:
                axis, angle = rotation
                sg.orient_axis(cache[f], (cache[f].x, cache[f].y, cache[f].z)[axis], angle)
            else:
                sg.orient_explicit(cache[f], dcm)             # sympy: f.dcm(g) = dcm
            # kept before its angular velocity is read: W_B_N> is often given in B itself
            cache[g] = sg
            try:
                w = to_sympy_vector(g.ang_vel_in(f), frames=cache, mapping=mapping,
                                    keep=keep)
                sg.set_ang_vel(cache[f], w)
            except AutolevModelError:
                w = None
            if orientations is not None:
                orientations.append((cache[f], sg, dcm, w))
            todo.append(g)
    return cache[frame]


def to_sympy_vector(v: "Vector", frames: dict | None = None, mapping: dict | None = None,
                    keep=frozenset()):
    """A sympy.physics.vector.Vector equal to v (the definitions of `keep` not expanded)."""
    me = _mechanics()
    total = me.Vector(0)
    for f, comps in v.terms.items():
        sf = (frames or {}).get(f) or to_sympy_frame(f, mapping, frames, keep=keep)
        m = mapping if mapping is not None else dynamic_map(f.scene)
        c = [to_sympy_expr(f.scene, x, m, keep) for x in comps]
        total += c[0] * sf.x + c[1] * sf.y + c[2] * sf.z
    return total


def to_sympy_point(point):
    me = _mechanics()
    return me.Point(point.name)


def symbolic_system(model, form: str = "combined"):
    """Kane's equations as a sympy.physics.mechanics.SymbolicSystem.

    form "explicit": x' = F(x); "combined": M(x) x' = F(x) for the whole state;
    "separate": q' = G(q, u) and M u' = f kept apart.  With dependent speeds the state
    ends with them and their constraint rows are marked algebraic (alg_con)."""
    me = _mechanics()
    mapping = dynamic_map(model.scene)
    eqs = model.equations()
    qs = [mapping[q] for q in model.coordinates]
    us = [mapping.get(u, u) for u in eqs.speeds]
    dep = [mapping[u] for u in model.dependent_speeds]
    kin = model.kinematical_equations
    kin_rhs = sm.Matrix([to_sympy_expr(model.scene, kin[S.derivative(q)], mapping)
                         for q in model.coordinates])
    mm = to_sympy_expr(model.scene, model.mass_matrix, mapping)
    f = to_sympy_expr(model.scene, model.forcing, mapping)
    nq, nu, nd = len(qs), len(us), len(dep)
    states = qs + us + dep
    dep_values = [to_sympy_expr(model.scene, model.defs.rhs[u], mapping)
                  for u in model.dependent_speeds]
    alg = sm.Matrix([d - v for d, v in zip(dep, dep_values)])
    n = nq + nu + nd
    full_m = sm.zeros(n, n)
    full_m[:nq, :nq] = sm.eye(nq)
    full_m[nq:nq + nu, nq:nq + nu] = mm
    full_f = sm.Matrix.vstack(kin_rhs, f, -alg) if nd else sm.Matrix.vstack(kin_rhs, f)
    alg_con = list(range(nq + nu, n)) if nd else None
    bodies = None
    if form == "combined":
        return me.SymbolicSystem(states, full_f, mass_matrix=full_m, alg_con=alg_con,
                                 coord_idxs=list(range(nq)),
                                 speed_idxs=list(range(nq, nq + nu)), bodies=bodies)
    if form == "separate":
        dyn_m = sm.zeros(nu + nd, nu + nd)
        dyn_m[:nu, :nu] = mm
        dyn_f = sm.Matrix.vstack(f, -alg) if nd else f
        return me.SymbolicSystem(states, dyn_f, coordinate_derivatives=kin_rhs,
                                 mass_matrix=dyn_m,
                                 alg_con=[nu + k for k in range(nd)] if nd else None,
                                 coord_idxs=list(range(nq)),
                                 speed_idxs=list(range(nq, nq + nu)))
    if form == "explicit":
        if nd:
            raise AutolevModelError("the explicit form needs no algebraic rows; with "
                                    "dependent speeds use form='combined' or 'separate'")
        udot = mm.LUsolve(f)
        return me.SymbolicSystem(states, sm.Matrix.vstack(kin_rhs, udot),
                                 coord_idxs=list(range(nq)),
                                 speed_idxs=list(range(nq, nq + nu)))
    raise ValueError(f"form must be 'explicit', 'combined' or 'separate', not {form!r}")
