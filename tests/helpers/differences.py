"""Derivatives by five-point central differences, and the rule for agreeing with them
(Model.dynamics' Jacobians: the examples' test and the corpus test); and two routes'
Jacobians held to each other."""
import numpy as np

STEPS = (1e-2, 1e-3, 1e-4, 1e-5)


def central(function, arrays: dict, name: str, scale=None) -> np.ndarray:
    """d function / d arrays[name] by five-point central differences, at each of STEPS
    (steps x nodes x rows x columns); `scale`: per column, what the steps are relative
    to (default 1: a mass of 1e-23 kg is stepped by 1e-25, not 1e-2)."""
    base = arrays[name]
    scale = np.ones(base.shape[-1]) if scale is None else np.asarray(scale, dtype=float)
    by_step = []
    for h in STEPS:
        columns = []
        for j in range(base.shape[-1]):
            step_j = h * scale[j]

            def at(step):
                moved = base.copy()
                moved[..., j] += step * step_j
                return function(**dict(arrays, **{name: moved}))
            columns.append((8 * (at(1) - at(-1)) - (at(2) - at(-2))) / (12 * step_j))
        by_step.append(np.stack(columns, axis=-1))
    return np.array(by_step)


def agrees(exact, differences) -> bool:
    """Each entry within 1e-8 of its row's size at the step that suits it: truncation
    (h^4 f^(5)) falls and rounding (eps f / h) grows as the step shrinks, and near a
    singular mass matrix (the Whipple's, the four-bar's off its constraint) no one step
    suits every entry; a missing or wrong term suits none."""
    scale = np.maximum(1.0, np.abs(differences[1]).max(axis=-1, keepdims=True))
    return bool(np.all(np.abs(exact - differences).min(axis=0) <= 1e-8 * scale))


def disagreements(exact, differences) -> tuple[int, int]:
    """(entries that disagree, entries the differences cannot decide): an entry is
    decided where two neighbouring steps' differences agree with each other within
    agrees()' tolerance, and then disagrees when no step's difference is within it of
    `exact`.  Where rounding swamps every step (a parameter of 1e-24 in an equation of
    size 1e-13; a mass matrix of condition 1e11 in f), nothing is decided."""
    scale = np.maximum(1.0, np.abs(differences[1]).max(axis=-1, keepdims=True))
    tolerance = 1e-8 * scale
    settled = (np.abs(np.diff(differences, axis=0)) <= tolerance).any(axis=0)
    close = (np.abs(exact - differences) <= tolerance).any(axis=0)
    return int((settled & ~close).sum()), int((~settled & ~close).sum())


def assert_same_jacobians(ours, theirs, tolerance: float) -> None:
    """Every block of `theirs` (a Jacobians) in `ours` too, each entry within `tolerance`
    of the block's largest entry (at least 1)."""
    for block in theirs.values:
        expected = theirs.dense(block)
        assert np.allclose(ours.dense(block), expected, rtol=0,
                           atol=tolerance * np.abs(expected).max(initial=1.0)), block
