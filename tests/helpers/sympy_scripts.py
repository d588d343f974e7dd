"""Checking a script of `autolev convert --to sympy` against the model it came from: run
where autolev cannot be imported, its equations at 20 random times, states, constants and
specified values, then `python SCRIPT.py OUT.csv`; against our Kane's equations
(mechanics level: the full mass matrix and forcing entry by entry, from
Model.symbolic_system) or our compiled right-hand side (equations level: the rates), and
`simulate`'s rows with the same method and tolerances."""
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me

from autolev.engine.options import RunOptions
from autolev.runtime.numerics.prepare import prepare_command

# in a process where autolev cannot be imported: the script's equations at random points
# (mechanics: kane's full mass matrix and forcing as the script takes them, auxiliary
# speeds 0, dependent speeds where the velocity constraints hold and are well
# conditioned; equations: its mass and forcing functions), printed as JSON, then its own
# main writing OUT.csv (the tests of the shipped examples run `python SCRIPT.py` itself)
DRIVER = """
import json, runpy, sys
sys.modules['autolev'] = None
import numpy as np, sympy as sm
script, csv = sys.argv[1:3]
ns = runpy.run_path(script)
rng = np.random.default_rng(33)
constants, specified = list(ns['constants']), list(ns['specified'])
# as Dummies: a model's constant may be named as numpy's functions (sin), which a nested
# argument list of lambdify would not rename
as_dummy = {c: sm.Dummy(str(c)) for c in constants}
placeholders = [as_dummy[c] for c in constants]
if 'kane' in ns:
    kane = ns['kane']
    states = list(kane.q) + list(kane.u)
    f = sm.lambdify([ns['t'], states, placeholders, specified],
                    [ns['full_mass'].xreplace(as_dummy), ns['full_forcing'].xreplace(as_dummy)],
                    cse=True)
    level = 'mechanics'
else:
    states = ns['states']
    mass, force, _ = ns['numeric_functions']()
    f = lambda *a: (mass(*a), force(*a))
    level = 'equations'
dependent = ns.get('dependent', [])
if dependent:
    # the dependent speeds where the velocity constraints hold (auxiliary speeds 0)
    import sympy.physics.mechanics as me
    zero = dict.fromkeys(ns.get('auxiliary', []), 0)
    a, b = sm.linear_eq_to_matrix([me.msubs(c, kane.kindiffdict(), zero)
                                   for c in ns['velocity_constraints']], dependent)
    held = sm.lambdify([ns['t'], states[:-len(dependent)], placeholders, specified],
                       [a.xreplace(as_dummy), b.xreplace(as_dummy)])
def named(s):
    # a rate of a specified quantity (mechanics level) by its name and primes: px''
    if isinstance(s, sm.Derivative):
        return str(s.expr.func) + "'" * s.derivative_count
    return str(s.func)
points, tries = [], 0
while len(points) < 20:
    tries += 1
    if tries > 1000:
        sys.exit('the velocity constraints are singular at every random state tried')
    t, x = rng.uniform(0, 2), rng.uniform(-1, 1, len(states))
    p, s = rng.uniform(0.5, 1.5, len(constants)), rng.uniform(-1, 1, len(specified))
    if level == 'equations' or dependent:
        s = 0 * s            # as our compiled rates take them (0 unless the model gives them)
    if dependent:
        a, b = (np.asarray(v, dtype=float) for v in held(t, x[:-len(dependent)], p, s))
        if np.linalg.cond(a) > 1e6:
            continue         # near where the constraints are singular: no digits to compare
        x[-len(dependent):] = np.linalg.solve(a, b.ravel())
    m, F = f(t, x, p, s)
    points.append([t, x.tolist(), p.tolist(), s.tolist(), np.asarray(m, dtype=float).tolist(),
                   np.asarray(F, dtype=float).ravel().tolist()])
print(json.dumps({'level': level, 'dependent': len(dependent),
                  'states': [str(s.func) for s in states],
                  'constants': [str(c) for c in constants],
                  'specified': [named(s) for s in specified], 'points': points}))
sys.stdout.flush()
# what `python SCRIPT.py CSV` runs, without sympy forming kane's equations once more
sys.exit(ns['main']([csv]))
"""


def run_script(script: Path, csv: Path, timeout: float = 600) -> dict:
    """The driver's JSON (level, names, and per point t, x, p, s, mass, forcing)."""
    done = subprocess.run([sys.executable, "-c", DRIVER, str(script), str(csv)],
                          capture_output=True, text=True, timeout=timeout)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout)


def largest_difference(theirs, ours) -> float:
    """max |theirs - ours| relative to the largest entry of ours (at least 1)."""
    theirs, ours = np.asarray(theirs, dtype=float), np.asarray(ours, dtype=float)
    assert theirs.shape == ours.shape, (theirs.shape, ours.shape)
    return float(np.abs(theirs - ours).max(initial=0.0) / max(1.0, np.abs(ours).max(initial=0)))


def equations_difference(model, command, found: dict) -> float:
    """The largest relative difference between the script's equations and ours over the
    driver's points: the full mass matrix and forcing (mechanics level), the rates solved
    from them (equations level, and mechanics level with dependent speeds, whose sympy
    form differs from ours: against our compiled right-hand side)."""
    if found["level"] == "mechanics" and not found["dependent"]:
        system = model.symbolic_system("combined")
        # a speed that is a coordinate's rate (X' declared) is X_rate in sympy
        names = [str(s.args[0].func) + "_rate" if isinstance(s, sm.Derivative)
                 else str(s.func) for s in system.states]
        assert names == found["states"]
        # the model's constants, as everything handed to sympy names them; a VARIABLE
        # nothing defines is one of them in a run (symbolic_system keeps it a function)
        constants = [sm.Dummy(n) for n in found["constants"]]
        as_run = {me.dynamicsymbols(c.name): c for c in constants}
        as_run.update({sm.Symbol(c.name): c for c in constants})
        ours = sm.lambdify([me.dynamicsymbols._t, system.states, constants,
                            [specified_named(n) for n in found["specified"]]],
                           [m.xreplace(as_run) for m in (system.comb_implicit_mat,
                                                         system.comb_implicit_rhs)],
                           cse=True)     # expanded, the sprinters' print for minutes
        worst = 0.0
        for t, x, p, s, mass, forcing in found["points"]:
            our_mass, our_forcing = ours(t, x, p, s)
            worst = max(worst, largest_difference(mass, our_mass),
                        largest_difference(forcing, np.asarray(our_forcing).ravel()))
        return worst
    # the constants' values are the driver's (set_parameters): none is needed here
    system = prepare_command(model.snapshot_for(command), command,
                             RunOptions(missing_values="zero")).system
    # in the run's order (sympy's dependent speeds after them); named as identifiers (X'
    # as Xp, a name the script uses renamed)
    n = len(system.states)
    assert len(found["states"]) == n + found["dependent"]
    assert len(found["constants"]) == len(system.params)
    worst = 0.0
    for t, x, p, s, mass, forcing in found["points"]:
        system.set_parameters(p)
        ours = system.derivatives(t, np.asarray(x[:n]))
        theirs = np.linalg.solve(np.asarray(mass), np.asarray(forcing))[:n]
        worst = max(worst, largest_difference(theirs, ours))
    return worst


def specified_named(name: str):
    """The dynamicsymbol of a specified quantity by the driver's name, or its rate (px'')."""
    base = name.rstrip("'")
    order = len(name) - len(base)
    f = me.dynamicsymbols(base)
    return f.diff(me.dynamicsymbols._t, order) if order else f


def rows_difference(model, csv: Path, rows: int | None = None, **inputs) -> float:
    """The largest difference, relative to each column's largest value (at least 1),
    between the script's rows and `simulate`'s (DOP853, the model's tolerances unless
    `inputs` give others, as the script was exported with); over the first `rows` rows
    only, when given."""
    result = model.simulate(method="dop853", **inputs)
    assert csv.read_text().splitlines()[0].split(",") == [
        label for t in result.outputs for label in t.labels] or [""]
    if not result.outputs:
        return 0.0                   # no OUTPUT: the header is empty, as are the rows
    ours = np.column_stack([t.data for t in result.outputs])
    theirs = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    assert theirs.shape == ours.shape, (theirs.shape, ours.shape)
    return float(column_relative(theirs, ours)[:rows].max())


def column_relative(theirs, ours) -> np.ndarray:
    """Each row's largest difference, relative to each column's largest value in `ours`
    (at least 1)."""
    return (np.abs(theirs - ours) / np.maximum(1.0, np.abs(ours).max(axis=0))).max(axis=1)
