"""Model.dynamics over the public corpus (issue 53): for every visible model whose first
CODE DYNAMICS runs (over 1 s, with the values the journeys give it: INPUT, the .in its
repository ships, then 1 for each constant still without a value, 0 for a product of
inertia), the exact Jacobians of f and of r equal five-point central differences at
two states of that run (its first row and its middle one), by the rule of the examples'
test: each entry within 1e-8 of its row's size at the step that suits it (a parameter's
steps relative to its value), wherever two neighbouring steps agree with each other.
Where rounding swamps or fools the differences, CasADi's algorithmic derivatives of the
same program decide the block (f's through r's, by a pivoted solve); without casadi
such entries are counted undecided, not passed.  A tree's Jacobians by its recursions
(r's by Newton-Euler, f's -M^-1 times them, solved in the program) also equal those
by its mass matrix."""
from pathlib import Path

import numpy as np
import pytest

import autolev
from autolev.engine.errors import AutolevModelError
from helpers.corpus_runs import corpus_cases, guarded, results_of, run_with_values
from helpers.differences import central, disagreements

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

LIMIT = 1500          # seconds for one model: build, run, form and compile its Jacobians
INPUTS = {"TFINAL": 1}


def check_model(case) -> dict:
    """One model: {'id', 'outcome' (not built / not run / agrees / failing), 'detail'}."""
    return guarded(_check, case, {"id": case[0], "outcome": "agrees", "detail": ""}, LIMIT)


def _check(path: Path, shipped: Path | None, out: dict) -> None:
    try:
        model = autolev.load(path)
    except autolev.AutolevError as exc:
        out.update(outcome="not built", detail=str(exc).splitlines()[0][:120])
        return
    if not any(c.kind.name == "DYNAMICS" for c in model.code_commands):
        out.update(outcome="not run", detail="no CODE DYNAMICS")
        return
    try:
        result, values = run_with_values(model, path, shipped, INPUTS)
    except AutolevModelError as exc:
        out.update(outcome="not run", detail=str(exc).splitlines()[0][:120])
        return
    if result.kind.name != "DYNAMICS" or len(result.t) == 0:
        out.update(outcome="not run", detail="its first program is not its CODE DYNAMICS")
        return
    if not result.ok and len(result.t) < 2:     # (values by rule: a singular mass matrix)
        out.update(outcome="not run", detail=result.failure.splitlines()[0][:120])
        return
    dynamics = model.dynamics(infile=shipped, overrides=values)
    rows = [0, len(result.t) // 2]
    where = [result.state_names.index(name) for name in dynamics.states]
    x = result.states[rows][:, where]
    rng = np.random.default_rng(11)
    u = 0.1 * rng.normal(size=(len(rows), len(dynamics.controls)))
    p, t = dynamics.parameter_values, result.t[rows]
    xdot = dynamics.explicit(x, u, p, t)
    explicit = dynamics.explicit_jacobians(x, u, p, t)
    implicit = dynamics.residual_jacobians(x, xdot, u, p, t)
    arrays = dict(x=x, u=u, p=p, t=t)

    def f(x, u, p, t):
        return dynamics.explicit(x, u, p, t)

    def r(x, u, p, t):
        return dynamics.residual(x, xdot, u, p, t)
    # parameters span scales (SSOpt's cell: masses of 1e-23 kg): stepped relative to each
    scales = {"x": None, "u": None, "p": np.where(p != 0, np.abs(p), 1.0)}
    wrong, undecided = [], 0
    checks = [(f"df/d{b}", explicit.dense(b), central(f, arrays, b, scales[b])) for b in
              ("x", "u", "p") if arrays[b].shape[-1]]
    checks += [(f"dr/d{b}", implicit.dense(b), central(r, arrays, b, scales[b])) for b in
               ("x", "u", "p") if arrays[b].shape[-1]]
    checks.append(("dr/dxdot", implicit.dense("xdot"),
                   central(lambda xdot: dynamics.residual(x, xdot, u, p, t), {"xdot": xdot},
                           "xdot")))
    # f's Jacobian is -M^-1 times r's: no second method can fix it better than cond(M) eps
    conditions = [np.linalg.cond(m) if m.size else 1.0
                  for m in dynamics.mass_matrix(x, u, p, t)]
    by_casadi, decided, ill = None, [], max(conditions) * np.finfo(float).eps > 1e-8
    for name, exact, differences in checks:
        disagree, cannot = disagreements(exact, differences)
        if disagree or cannot:
            # differences swamped or fooled by rounding (SSOpt's computed torques give
            # r ~ 1e-41 out of terms of 1e-19, a sprinter's contact forces of 1e5 beside
            # entries of 1): CasADi's own derivatives of the same program decide the block
            by_casadi = by_casadi or _casadi_jacobians(dynamics, x, xdot, u, p, t)
            if by_casadi is not None:
                theirs = by_casadi[name[1], name[name.index("/") + 2:]]
                scale = np.maximum(1.0, np.abs(theirs).max(axis=-1, keepdims=True))
                disagree, cannot = int((np.abs(exact - theirs) > 1e-8 * scale).sum()), 0
                decided.append(name)
        if disagree and ill and name.startswith("df/"):
            disagree, cannot = 0, cannot + disagree
        undecided += cannot
        if disagree:
            wrong.append(f"{name} ({disagree} entries)")
    if explicit.by == "recursion":      # a tree's: the mass matrix's route as well
        assert implicit.by == "recursion"
        wrong += _routes_differ(model.dynamics(infile=shipped, overrides=values,
                                               recursion=False), explicit, implicit, x, xdot,
                                u, p, t, ill)
    out["detail"] = (f"{len(dynamics.states)} states, {len(dynamics.parameters)} parameters"
                     + f"; f's Jacobians by the {explicit.by}"
                     + (f"; decided by CasADi's derivatives: {', '.join(decided)}"
                        if decided else "")
                     + (f"; {undecided} entries undecided (rounding"
                        + (f"; cond(M) {max(conditions):.0e}" if ill else "") + ")"
                        if undecided else "")
                     + (f"; differ: {', '.join(wrong)}" if wrong else ""))
    if wrong:
        out["outcome"] = "failing"


def _routes_differ(mass, explicit, implicit, x, xdot, u, p, t, ill: bool) -> list:
    """The blocks where a tree's Jacobians by its recursions and by its mass matrix
    differ beyond 1e-8 of their row's size: f's (by -M^-1 times those of M a - F;
    nothing where M's condition alone could part them) and r's (M a - F as formed)."""
    wrong = []
    for form, by_tree, by_mass in (
            ("f", explicit, mass.explicit_jacobians(x, u, p, t)),
            ("r", implicit, mass.residual_jacobians(x, xdot, u, p, t))):
        for block in by_mass.values:
            expected = by_mass.dense(block)
            if not expected.size:           # no controls
                continue
            scale = np.maximum(1.0, np.abs(expected).max(axis=-1, keepdims=True))
            apart = int((np.abs(by_tree.dense(block) - expected) > 1e-8 * scale).sum())
            if apart and not (ill and form == "f"):
                wrong.append(f"d{form}/d{block} by the recursion and by M a - F "
                             f"({apart} entries)")
    return wrong


def _casadi_jacobians(dynamics, x, xdot, u, p, t) -> dict | None:
    """{("f" or "r", block): nodes x rows x columns}: r's Jacobians by CasADi's algorithmic
    differentiation of the same program, at x' = f's rates, and f's from them as
    -(dr/dx')^-1 dr/d(block) by a pivoted LU (CasADi's own symbolic solve loses digits
    where M's condition is 1e6); None without casadi."""
    try:
        import casadi as ca
    except ImportError:
        return None
    form = dynamics.casadi()
    symbols = {"x": ca.SX.sym("x", x.shape[1]), "xdot": ca.SX.sym("xdot", x.shape[1]),
               "u": ca.SX.sym("u", u.shape[1]), "p": ca.SX.sym("p", len(p))}
    time = ca.SX.sym("t")
    r = form.residual(symbols["x"], symbols["xdot"], symbols["u"], symbols["p"], time)
    blocks = ("x", "u", "p", "xdot")
    jacobians = ca.Function("jacobians", [*symbols.values(), time],
                            [ca.jacobian(r, symbols[b]) for b in blocks])
    out: dict = {}
    for k in range(x.shape[0]):
        values = dict(zip(blocks, (np.array(v) for v in
                                   jacobians(x[k], xdot[k], u[k], p, t[k]))))
        for b in blocks:
            out.setdefault(("r", b), []).append(values[b])
            if b != "xdot":
                out.setdefault(("f", b), []).append(-np.linalg.solve(values["xdot"],
                                                                      values[b]))
    return {key: np.array(values) for key, values in out.items()}


def test_every_corpus_models_jacobians_are_central_differences(corpus):
    results = results_of(check_model, corpus_cases(corpus))
    agreeing = [r for r in results if r["outcome"] == "agrees"]
    failing = [r for r in results if r["outcome"] == "failing"]
    print(f"\n{len(results)} models; {len(agreeing) + len(failing)} run their CODE "
          f"DYNAMICS; {len(agreeing)} agree; {len(failing)} failing")
    for r in sorted(results, key=lambda r: (r["outcome"], r["id"])):
        print(f"{r['outcome']:10} {r['id']}: {r['detail']}")
    assert not failing
    assert len(agreeing) >= 30           # 31 at the time of writing
