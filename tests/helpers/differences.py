"""Derivatives by five-point central differences, and the rule for agreeing with them
(Model.dynamics' Jacobians: the examples' test and the corpus test)."""
import numpy as np

STEPS = (1e-2, 1e-3, 1e-4, 1e-5)


def central(function, arrays: dict, name: str) -> np.ndarray:
    """d function / d arrays[name] by five-point central differences, at each of STEPS
    (steps x nodes x rows x columns)."""
    base = arrays[name]
    by_step = []
    for h in STEPS:
        columns = []
        for j in range(base.shape[-1]):
            def at(step):
                moved = base.copy()
                moved[..., j] += step * h
                return function(**dict(arrays, **{name: moved}))
            columns.append((8 * (at(1) - at(-1)) - (at(2) - at(-2))) / (12 * h))
        by_step.append(np.stack(columns, axis=-1))
    return np.array(by_step)


def agrees(exact, differences) -> bool:
    """Each entry within 1e-8 of its row's size at the step that suits it: truncation
    (h^4 f^(5)) falls and rounding (eps f / h) grows as the step shrinks, and near a
    singular mass matrix (the Whipple's, the four-bar's off its constraint) no one step
    suits every entry; a missing or wrong term suits none."""
    scale = np.maximum(1.0, np.abs(differences[1]).max(axis=-1, keepdims=True))
    return bool(np.all(np.abs(exact - differences).min(axis=0) <= 1e-8 * scale))
