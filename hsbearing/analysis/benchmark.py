"""Synthetic cage-centre motions whose answer is known: the benchmark of the motion classifier.

Each generator returns a :class:`Motion` (time, D_Y, D_Z, V_Y, V_Z, cage angle, the expected label and
the labels that are also acceptable) sampled like a real run of the bundled case: cage speed 96 rev/s
(5760 r/min, the 7206 bearing at 14000 r/min), output every 50 us (~208 samples per cage revolution),
guide clearance 200 um.  Velocities are the exact derivatives (a real run stores them as states), so the
noise added by :func:`with_noise` is independent in every coordinate, as integration error would be.

:func:`cases` lists the whole benchmark (docs/analysis.md, "Synthetic benchmark"; tests/analysis/test_classify_benchmark.py):
circles at whirl/cage ratios 0.95, 0.98, 1.00, 1.02 with and without a ball-pass ripple; exact 3- and
4-loop epicycles; a two-frequency torus; a 1:1 locking transient; a growing and a decaying spiral; a
micro-vibration of a cage resting off-centre; the Rössler chaotic flow projected on (x, y); 2-D
Ornstein-Uhlenbeck noise -- each at two noise levels and two run lengths.  Thresholds of the classifier
are set on this benchmark, never on the labels of a paper.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field, replace

import numpy as np

__all__ = ["Motion", "CAGE_SPEED", "CLEARANCE", "BALLS", "circle", "epicycle", "torus", "locking_transient",
           "spiral", "micro_vibration", "rossler", "ou_noise", "with_noise", "positions_only", "cases", "NOISE_LEVELS",
           "PROBE_NOISE", "LENGTHS", "replace"]

#: Cage rotation speed [rad/s] (96 rev/s).
CAGE_SPEED = 2 * math.pi * 96.0
#: Radial guide clearance [m].
CLEARANCE = 200e-6
#: Ball count (ball-pass frequency = BALLS x cage speed).
BALLS = 11
#: Output interval [s].
DT = 50e-6
#: Whirl radius of the regular motions [m].
RADIUS = 100e-6
#: Additive noise levels: fraction of the whirl radius (positions) and of radius x cage speed (velocities).
NOISE_LEVELS = (0.002, 0.01)
#: Noise of a proximity-probe record (fraction of the whirl radius) for the position-only variants: 2 %.
PROBE_NOISE = 0.02
#: Run lengths: cage revolutions in the analysed window (short ~ a 1.2 s study run after its transient).
LENGTHS = {"short": 80, "long": 400}


@dataclass(frozen=True)
class Motion:
    """A synthetic cage-centre motion and the answer it has."""

    name: str
    t: np.ndarray
    y: np.ndarray
    z: np.ndarray
    vy: np.ndarray
    vz: np.ndarray
    phi: np.ndarray
    expected: str
    also: tuple = ()  # labels that are also correct answers (e.g. "undetermined" for a short chaotic run)
    kind: str = ""  # the expected reading (still, growing, ...), if the label alone does not say it
    info: dict = field(default_factory=dict)

    def accepts(self, label: str) -> bool:
        return label == self.expected or label in self.also


def _time(revs: float) -> np.ndarray:
    return np.arange(int(round(revs * 2 * math.pi / CAGE_SPEED / DT)) + 1) * DT


def _complex(name, t, w, dw, expected, also=(), kind="", **info) -> Motion:
    """Motion from the complex position w = y + i z and its time derivative dw."""
    phi = CAGE_SPEED * t
    return Motion(name, t, w.real.copy(), w.imag.copy(), dw.real.copy(), dw.imag.copy(), phi, expected, tuple(also),
                  kind, info)


def circle(ratio: float, ripple: float = 0.0, revs: float = 80, phase: float = 0.3) -> Motion:
    """Circular whirl at ``ratio`` x the cage speed; ``ripple``: ball-pass ripple of the velocity.

    The radius is modulated at the ball-pass frequency BALLS x cage speed with a relative amplitude
    ``ripple / BALLS``, so the velocity carries a ripple of about ``ripple`` x the whirl speed (and the
    position ripple / 11 of it).  Answer: "1 period" at every ratio (one loop per whirl turn).
    """
    t = _time(revs)
    wb = BALLS * CAGE_SPEED
    a = ripple / BALLS
    th = ratio * CAGE_SPEED * t + phase
    rad = RADIUS * (1 + a * np.cos(wb * t))
    drad = -RADIUS * a * wb * np.sin(wb * t)
    e = np.exp(1j * th)
    return _complex(f"circle {ratio:.2f}" + (f" + {100 * ripple:g} % ball-pass" if ripple else ""), t, rad * e,
                    (drad + 1j * rad * ratio * CAGE_SPEED) * e, "1 period")


def epicycle(k: int, ratio: float = 0.97, a: float = 0.25, revs: float = 80) -> Motion:
    """k-loop orbit: whirl at ``ratio`` x cage speed plus a component at 1/k of it (a times the radius).

    The small phase advances by 1/k turn per whirl turn, so the orbit closes after k turns and crosses the
    section at k distinct points.  Answer: "k periods".
    """
    t = _time(revs)
    w1 = ratio * CAGE_SPEED
    w2 = w1 / k
    w = RADIUS * np.exp(1j * w1 * t) + a * RADIUS * np.exp(1j * (w2 * t + 0.7))
    dw = 1j * w1 * RADIUS * np.exp(1j * w1 * t) + 1j * w2 * a * RADIUS * np.exp(1j * (w2 * t + 0.7))
    return _complex(f"epicycle period {k}", t, w, dw, f"{k} periods")


def torus(ratio: float = 0.97, a: float = 0.25, revs: float = 80) -> Motion:
    """Two-frequency orbit: whirl plus a component at (sqrt 5 - 1)/2 of its frequency.  Answer: quasi-periodic."""
    t = _time(revs)
    w1 = ratio * CAGE_SPEED
    w2 = w1 * (math.sqrt(5) - 1) / 2
    w = RADIUS * np.exp(1j * w1 * t) + a * RADIUS * np.exp(1j * w2 * t)
    dw = 1j * w1 * RADIUS * np.exp(1j * w1 * t) + 1j * w2 * a * RADIUS * np.exp(1j * w2 * t)
    return _complex("torus (golden)", t, w, dw, "quasi-periodic")


def locking_transient(revs: float = 80, detune: float = 0.05) -> Motion:
    """Circular whirl whose speed locks onto the cage speed: ratio(t) = 1 + detune exp(-t / tau).

    tau = a quarter of the window.  The orbit is a circle throughout: answer "1 period" (the transverse
    section gives one point); the cage-revolution section shows points converging along an arc.
    """
    t = _time(revs)
    tau = 0.25 * t[-1]
    th = CAGE_SPEED * (t + detune * tau * (1 - np.exp(-t / tau)))
    dth = CAGE_SPEED * (1 + detune * np.exp(-t / tau))
    e = np.exp(1j * th)
    return _complex("locking transient 1:1", t, RADIUS * e, 1j * dth * RADIUS * e, "1 period")


def spiral(factor: float, revs: float = 80, ratio: float = 0.97, r0: float = 40e-6) -> Motion:
    """Exponential spiral: the radius changes by ``factor`` over the window.  Answer: undetermined (growing/decaying)."""
    t = _time(revs)
    sigma = math.log(factor) / t[-1]
    w1 = ratio * CAGE_SPEED
    w = r0 * np.exp((sigma + 1j * w1) * t)
    dw = (sigma + 1j * w1) * w
    return _complex("growing spiral" if factor > 1 else "decaying spiral", t, w, dw, "undetermined",
                    kind="growing" if factor > 1 else "decaying", sigma=sigma)


def micro_vibration(revs: float = 80, offset: float = 150e-6, amp: float = 1e-6) -> Motion:
    """Cage resting off-centre (pressed on its land) with an ``amp`` ball-pass vibration.  Answer: 1 period (still)."""
    t = _time(revs)
    wb = BALLS * CAGE_SPEED
    w = offset + amp * (np.cos(wb * t) + 0.5j * np.sin(wb * t))
    dw = amp * wb * (-np.sin(wb * t) + 0.5j * np.cos(wb * t))
    return _complex(f"micro-vibration at ball pass ({amp * 1e6:g} um)", t, w, dw, "1 period", kind="still")


@functools.lru_cache(maxsize=4)
def rossler(revs: float = 80, ratio: float = 0.97, a: float = 0.2, b: float = 0.2, c: float = 5.7) -> Motion:
    """The Rössler flow (Rössler 1976; a = b = 0.2, c = 5.7, chaotic) projected on (x, y) as (D_Y, D_Z).

    Time is scaled so that the mean rotation about the origin runs at ``ratio`` x the cage speed and
    lengths so that |x| <= ~RADIUS.  Answer: chaos ("undetermined" also accepted on the short window,
    where the two indicators may not both be reached).
    """
    from scipy.integrate import solve_ivp

    def f(_, s):
        x, y, z = s
        return [-y - z, x + a * y, b + z * (x - c)]

    # settle on the attractor, then measure its mean angular speed to scale time
    s0 = solve_ivp(f, (0, 300), [1.0, 1.0, 0.0], rtol=1e-10, atol=1e-12, method="DOP853").y[:, -1]
    T_unit = 2 * math.pi / 1.0  # about one turn per 2 pi / (1 + ...) time units
    probe = solve_ivp(f, (0, 200 * T_unit), s0, rtol=1e-10, atol=1e-12, method="DOP853", dense_output=True)
    tp = np.linspace(0, 200 * T_unit, 40001)
    xp, yp = probe.sol(tp)[:2]
    w_mean = np.unwrap(np.arctan2(yp, xp))[-1] / tp[-1]  # mean angular speed [rad / time unit]
    scale_t = ratio * CAGE_SPEED / w_mean  # rossler time = scale_t * real time
    t = _time(revs)
    sol = solve_ivp(f, (0, scale_t * t[-1]), s0, rtol=1e-10, atol=1e-12, method="DOP853", dense_output=True)
    X, Y, Z = sol.sol(scale_t * t)
    L = RADIUS / 12.0
    dX, dY = -Y - Z, X + a * Y
    w = L * (X + 1j * Y)
    dw = L * scale_t * (dX + 1j * dY)
    return _complex("Rössler chaos", t, w, dw, "chaos", also=("undetermined",) if revs < 200 else ())


@functools.lru_cache(maxsize=4)
def ou_noise(revs: float = 80, seed: int = 5, corr_revs: float = 0.3) -> Motion:
    """2-D Ornstein-Uhlenbeck noise (correlation time 0.3 cage revolution), RMS = RADIUS.  Answer: undetermined."""
    rng = np.random.default_rng(seed)
    t = _time(revs)
    tau = corr_revs * 2 * math.pi / CAGE_SPEED
    k = math.exp(-DT / tau)
    q = RADIUS * math.sqrt(1 - k * k)
    w = np.empty(t.size, complex)
    w[0] = RADIUS * (rng.standard_normal() + 1j * rng.standard_normal()) / math.sqrt(2)
    e = q * (rng.standard_normal(t.size) + 1j * rng.standard_normal(t.size)) / math.sqrt(2)
    for i in range(1, t.size):
        w[i] = k * w[i - 1] + e[i]
    dw = np.gradient(w, t)
    return _complex("Ornstein-Uhlenbeck noise", t, w, dw, "undetermined", kind="irregular")


def with_noise(m: Motion, level: float, seed: int = 0) -> Motion:
    """``m`` with white noise: ``level`` x RADIUS on D_Y, D_Z and ``level`` x RADIUS x cage speed on V_Y, V_Z."""
    if level <= 0:
        return m
    rng = np.random.default_rng(seed)
    n = m.t.size
    s, sv = level * RADIUS, level * RADIUS * CAGE_SPEED
    return replace(m, name=f"{m.name}, noise {100 * level:g} %", y=m.y + s * rng.standard_normal(n),
                   z=m.z + s * rng.standard_normal(n), vy=m.vy + sv * rng.standard_normal(n),
                   vz=m.vz + sv * rng.standard_normal(n))


def positions_only(m: Motion) -> Motion:
    """``m`` as a proximity probe records it: the positions (with whatever noise they carry), no velocities.

    The velocities are set to NaN; :func:`hsbearing.analysis.whirl.classify_motion` is then called with
    ``vy = vz = None`` so that it estimates them (:mod:`hsbearing.analysis.derivative`).
    """
    nan = np.full_like(m.y, np.nan)
    return replace(m, name=f"{m.name}, positions only", vy=nan, vz=nan.copy(), info={**m.info, "positions_only": True})


def cases(length: str = "short", noise: float = 0.0, seed: int = 0) -> list[Motion]:
    """The whole benchmark at one run length ("short" 80, "long" 400 cage revolutions) and noise level."""
    revs = LENGTHS[length]
    base = [circle(r, ripple, revs) for r in (0.95, 0.98, 1.00, 1.02) for ripple in (0.0, 0.02)]
    base += [epicycle(3, revs=revs), epicycle(4, revs=revs), torus(revs=revs), locking_transient(revs),
             spiral(3.0, revs), spiral(1 / 4.0, revs), micro_vibration(revs), micro_vibration(revs, amp=6e-6),
             rossler(revs), ou_noise(revs)]
    return [with_noise(m, noise, seed + i) for i, m in enumerate(base)]
