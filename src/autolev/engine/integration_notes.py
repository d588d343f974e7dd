"""What a run tells the user of its integration: stiffness, tolerances too loose
for a method, why Kutta-Merson halved its step too often (numbers only, no model:
a warm run from its run plan reads this without sympy).
"""
from __future__ import annotations

import warnings

import numpy as np

from .integrate import Integration, IntegrationFailure
from .integrators import LSODA, RADAU, Integrator


def switch_when_stiff(t: float, hlamb: float) -> Integrator:
    # Radau, not LSODA: on the lightly damped stiff spring chain of
    # bench/work_precision.py LSODA took 1.4 ms to 680 ms depending on the tolerance,
    # Radau 5 to 133 ms at every tolerance
    warnings.warn(f"the equations are stiff from T = {t:.6g} (step size times the largest "
                  f"eigenvalue ~ {hlamb:.3g}, beyond DOP853's stability): going on with "
                  f"{RADAU.scipy_name} (implicit); ask for --method {RADAU.name} from the "
                  "start to avoid the switch", stacklevel=2)
    return RADAU


def loose_tolerance_note(integrator: Integrator, relerr: float) -> None:
    limit = integrator.loose_relerr
    if relerr >= limit:
        warnings.warn(f"RELERR = {relerr:g} is loose for {integrator.name}: at RELERR >= "
                      f"{limit:g} it is known to give qualitatively wrong motion over long "
                      "runs (a conservative double pendulum gains or loses over 1 % of its "
                      f"energy in 100 s); use RELERR <= {limit / 100:g}", stacklevel=4)


def stiff_note(stats: dict, integrator: Integrator) -> None:
    t = stats.get("stiff_t")
    if t is None or stats.get("switched_to"):
        return
    warnings.warn(f"the equations are stiff from T = {t:.6g}: {integrator.name}'s steps are "
                  "limited by its stability, not by the error asked for (a slow run); an "
                  f"implicit method (--method {LSODA.name} or {RADAU.name}; "
                  f"method='{LSODA.name}') takes far fewer steps", stacklevel=3)


# h*|lambda| where Kutta-Merson stops being stable on the negative real axis
KM_STABILITY = 3.5


def halving_verdict(integration: Integration, failure: IntegrationFailure) -> str:
    """Why Kutta-Merson's step was halved too often: zero tolerances, or stiffness
    (judged by the Jacobian's eigenvalues where it stopped), or neither."""
    abserr, relerr = integration.abserr, integration.relerr
    if abserr <= 0 and relerr <= 0:
        return ("ABSERR and RELERR are both 0, which no step can satisfy: give them "
                "values (e.g. ABSERR = 1E-8, RELERR = 1E-7)")
    floor = abs(integration.schedule.integstp) / 2 ** 20
    rho = spectral_radius(integration.f, failure.t, failure.y)
    if rho is None:
        return "the derivatives are not finite near that state"
    if rho * floor > KM_STABILITY:
        return (f"the equations are stiff there (the Jacobian's largest eigenvalue is "
                f"about {rho:.3g} in size: Kutta-Merson needs steps below "
                f"{KM_STABILITY / rho:.2g}, finer than the {floor:.2g} its 20 halvings of "
                f"INTEGSTP allow); an implicit method takes them in stride: --method "
                f"{RADAU.name} (method='{RADAU.name}')")
    verdict = (f"the equations are not stiff there (the Jacobian's largest eigenvalue is "
               f"about {rho:.3g} in size)")
    if abserr <= 0:
        return verdict + ("; ABSERR = 0 makes any state that is exactly 0 fail the error "
                          "test: give ABSERR a small value (e.g. 1E-8)")
    return verdict + ("; the derivatives may jump or grow without bound near that state, "
                      "or ABSERR and RELERR are below what double precision can meet")


def spectral_radius(f, t: float, y: np.ndarray) -> float | None:
    """max |eigenvalue| of df/dy at (t, y), by forward differences; None where the
    derivatives cannot be evaluated."""
    try:
        f0 = np.asarray(f(t, y), dtype=float)
        columns = []
        for j in range(len(y)):
            step = 1.5e-8 * max(1.0, abs(y[j]))
            moved = np.array(y, dtype=float)
            moved[j] += step
            columns.append((np.asarray(f(t, moved), dtype=float) - f0) / step)
    except IntegrationFailure:
        return None
    jac = np.array(columns).T
    if not np.all(np.isfinite(jac)):
        return None
    return float(np.max(np.abs(np.linalg.eigvals(jac)))) if len(y) else 0.0
