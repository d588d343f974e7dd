"""Kane's equations formed for bench/chains.py's generated models equal those of
sympy's KanesMethod for the same systems, built here from scratch.

The planar n-link pendulum (n = 1..4) and the 3-D chain of bodies in ball joints
(n = 1, 2; 3 bodies under `pytest -m slow`): at three random states and parameter
sets, the accelerations u' = M^-1 f solved from our mass matrix and forcing
(evaluated through the model's definitions, tests/mech.py) equal sympy's to a
relative 1e-9.
"""
from __future__ import annotations

import random
import sys

import numpy as np
import pytest
import sympy as sm
import sympy.physics.mechanics as me

import autolev
from helpers import ROOT
from helpers.mechanics import symbols, value

sys.path.insert(0, str(ROOT / "bench"))
import chains  # noqa: E402


def kanes_planar(n: int):
    """Links pinned end to end in N's x-y plane.  Link i turns by q_i about z relative
    to link i-1, u_i = q_i'; center of mass at L/2, the next pin at L along the
    link's x axis; central inertia M L^2/12 about z only; gravity G along N.x.
    Returns (M, f, q, u, constants) with M u' = f."""
    q, u = me.dynamicsymbols(f"a1:{n + 1}"), me.dynamicsymbols(f"w1:{n + 1}")
    length, mass, g = sm.symbols("length mass g")
    N = me.ReferenceFrame("N")
    pin = me.Point("pin0")
    pin.set_vel(N, 0)
    frame, bodies, loads = N, [], []
    for i in range(n):
        link = me.ReferenceFrame(f"link{i}")
        link.orient_axis(frame, frame.z, q[i])
        link.set_ang_vel(frame, u[i] * frame.z)
        cm = pin.locatenew(f"cm{i}", length / 2 * link.x)
        cm.v2pt_theory(pin, N, link)
        central = (me.inertia(link, 0, 0, mass * length ** 2 / 12), cm)
        bodies.append(me.RigidBody(f"link{i}", cm, link, mass, central))
        loads.append((cm, mass * g * N.x))
        end = pin.locatenew(f"pin{i + 1}", length * link.x)
        end.v2pt_theory(pin, N, link)
        frame, pin = link, end
    kane = me.KanesMethod(N, q, u, kd_eqs=[a.diff() - w for a, w in zip(q, u)])
    kane.kanes_equations(bodies, loads)
    return (kane.mass_matrix, kane.forcing, q, u,
            {"L": length, "M": mass, "G": g})


def kanes_chain3d(n: int):
    """Bodies in ball joints.  Body i is oriented relative to body i-1 by body-fixed
    1-2-3 angles; its three speeds are the components, in body i, of its angular
    velocity relative to body i-1 (the kinematical equations come from that
    definition); center of mass at L/2, the next joint at L along the body's z axis;
    central inertia diag(IXX, IYY, IZZ); gravity G along -N.z."""
    q, u = me.dynamicsymbols(f"a1:{3 * n + 1}"), me.dynamicsymbols(f"w1:{3 * n + 1}")
    length, mass, g, i1, i2, i3 = sm.symbols("length mass g i1 i2 i3")
    N = me.ReferenceFrame("N")
    pin = me.Point("pin0")
    pin.set_vel(N, 0)
    frame, bodies, loads, kinematics = N, [], [], []
    for i in range(n):
        angles, rates = q[3 * i:3 * i + 3], u[3 * i:3 * i + 3]
        body = me.ReferenceFrame(f"body{i}")
        body.orient_body_fixed(frame, angles, "123")
        omega = body.ang_vel_in(frame)
        kinematics += [omega.dot(axis) - w for axis, w in zip(body, rates)]
        body.set_ang_vel(frame, sum((w * axis for w, axis in zip(rates, body)),
                                    me.Vector(0)))
        cm = pin.locatenew(f"cm{i}", length / 2 * body.z)
        cm.v2pt_theory(pin, N, body)
        central = (me.inertia(body, i1, i2, i3), cm)
        bodies.append(me.RigidBody(f"body{i}", cm, body, mass, central))
        loads.append((cm, -mass * g * N.z))
        end = pin.locatenew(f"pin{i + 1}", length * body.z)
        end.v2pt_theory(pin, N, body)
        frame, pin = body, end
    kane = me.KanesMethod(N, q, u, kd_eqs=kinematics)
    kane.kanes_equations(bodies, loads)
    return (kane.mass_matrix, kane.forcing, q, u,
            {"L": length, "M": mass, "G": g, "IXX": i1, "IYY": i2, "IZZ": i3})


KANES = {"planar": kanes_planar, "chain3d": kanes_chain3d}


def check_accelerations(kind: str, n: int, folder) -> None:
    model = autolev.load(chains.write(kind, n, folder))
    M, f, q, u, constants = KANES[kind](n)
    theirs = sm.lambdify((q, u, list(constants.values())), [M, f])
    names = [s.name for s in model.speeds]
    dof = len(u)
    assert sorted(names) == sorted(f"U{i}" for i in range(1, dof + 1))
    mass_matrix, forcing = model.mass_matrix, model.forcing
    assert mass_matrix.shape == (dof, dof)
    rng = random.Random(f"{kind}{n}")
    for _ in range(3):
        qv = [rng.uniform(-1.0, 1.0) for _ in range(dof)]
        uv = [rng.uniform(-1.0, 1.0) for _ in range(dof)]
        cv = {name: rng.uniform(0.5, 2.0) for name in constants}
        cv["G"] = rng.uniform(5.0, 15.0)
        values = {symbols(model, f"Q{i}"): v for i, v in enumerate(qv, 1)}
        values.update((symbols(model, f"U{i}"), v) for i, v in enumerate(uv, 1))
        values.update((symbols(model, name), v) for name, v in cv.items())
        ours_m = np.array(value(model, mass_matrix, values), dtype=float)
        ours_f = np.array(value(model, forcing, values), dtype=float).ravel()
        ours = dict(zip(names, np.linalg.solve(ours_m, ours_f)))
        ours = np.array([ours[f"U{i}"] for i in range(1, dof + 1)])
        mm, ff = theirs(qv, uv, list(cv.values()))
        expected = np.linalg.solve(np.asarray(mm, float), np.asarray(ff, float).ravel())
        scale = max(1.0, float(np.max(np.abs(expected))))
        assert np.max(np.abs(ours - expected)) <= 1e-9 * scale, (qv, uv, cv, ours, expected)


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_planar_chain_equals_sympy_kanesmethod(n, tmp_path):
    check_accelerations("planar", n, tmp_path)


@pytest.mark.parametrize("n", [1, 2])
def test_3d_chain_equals_sympy_kanesmethod(n, tmp_path):
    check_accelerations("chain3d", n, tmp_path)


@pytest.mark.slow
def test_3d_chain_of_three_equals_sympy_kanesmethod(tmp_path):
    check_accelerations("chain3d", 3, tmp_path)
