"""KINDIFFS(N, B, BODYijk | SPACEijk, Q1, Q2, Q3) solved for the angles' rates, with
W_B_N> written in B's axes or in N's: each rate checked against sympy.physics.vector's
own orientation of B (orient_body_fixed / orient_space_fixed), whose angular velocity
at those rates must be the W_B_N> the model gave, at random angles and speeds."""
import itertools

import pytest
import sympy.physics.vector as spv

import autolev
from helpers.mechanics import symbols, value

SEQUENCES = [f"{kind}{a}{b}{c}" for kind in ("BODY", "SPACE")
             for a, b, c in itertools.product("123", repeat=3) if a != b and b != c]

MODEL = """NEWTONIAN N
BODIES B
MOTIONVARIABLES' Q{{3}}', U{{3}}'
DIRCOS(N, B, {sequence}, Q1, Q2, Q3)
W_B_N> = U1*{frame}1> + U2*{frame}2> + U3*{frame}3>
KINDIFFS(N, B, {sequence}, Q1, Q2, Q3)
"""


@pytest.mark.parametrize("frame", ["B", "N"])
@pytest.mark.parametrize("sequence", SEQUENCES)
def test_the_rates_give_the_angular_velocity_the_model_wrote(tmp_path, sequence, frame):
    path = tmp_path / "kin.al"
    path.write_text(MODEL.format(sequence=sequence, frame=frame))
    m = autolev.load(path)
    names = ["Q1", "Q2", "Q3", "U1", "U2", "U3"]
    # angles away from the sequence's singular middle angle (0 or 90 degrees)
    numbers = dict(zip(names, [0.7, 0.55, -1.1, 0.3, -0.8, 1.3]))
    given = {s: numbers[n] for s, n in zip(symbols(m, *names), names)}
    ours = [value(m, r, given) for r in symbols(m, "Q1'", "Q2'", "Q3'")]
    # sympy's frames, oriented by its own rules
    t = spv.dynamicsymbols._t
    q = spv.dynamicsymbols("q1:4")
    n = spv.ReferenceFrame("N")
    b = spv.ReferenceFrame("B")
    kind, axes = sequence[:-3], sequence[-3:]
    if kind == "BODY":
        b.orient_body_fixed(n, q, axes)
    else:
        b.orient_space_fixed(n, q, axes)
    at = {**{qi.diff(t): rate for qi, rate in zip(q, ours)},
          **{qi: numbers[f"Q{k}"] for k, qi in enumerate(q, start=1)}}
    written = n if frame == "N" else b
    w = b.ang_vel_in(n)
    for k, axis in enumerate((written.x, written.y, written.z), start=1):
        assert float(w.dot(axis).subs(at)) == pytest.approx(numbers[f"U{k}"], abs=1e-12)


def test_the_small_solve_reduces_by_the_pythagorean_identity_alone(tmp_path, monkeypatch):
    import sympy as sm
    from autolev.runtime.model import _pythagorean
    q2, q3 = sm.symbols("q2 q3")
    # SPACE313's determinant and a minor reduce; a lone COS^2 is shorter as it is
    assert _pythagorean(-sm.sin(q2) ** 3 - sm.sin(q2) * sm.cos(q2) ** 2) == -sm.sin(q2)
    assert _pythagorean(sm.sin(q2) * (sm.sin(q3) ** 2 + sm.cos(q3) ** 2)) == sm.sin(q2)
    assert _pythagorean(sm.cos(q3) ** 2) == sm.cos(q3) ** 2
    # no general simplifier on the way (trigsimp was a third of such a model's forming)
    def refused(*args, **kwargs):
        raise AssertionError("a general simplifier ran")
    for name in ("trigsimp", "simplify"):
        monkeypatch.setattr(sm, name, refused)
    path = tmp_path / "kin.al"
    path.write_text(MODEL.format(sequence="SPACE313", frame="B"))
    m = autolev.load(path)
    assert len(symbols(m, "Q1'", "Q2'", "Q3'")) == 3
