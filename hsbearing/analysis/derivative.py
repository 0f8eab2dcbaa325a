"""Velocity of the cage centre from its positions alone (a measured orbit, an archive without velocities).

Central differences (``numpy.gradient``) amplify white position noise of standard deviation s into a
velocity noise s / (sqrt 2 dt): with 0.2 um on a probe sampled every 50 us that is 2.8 mm/s, 5 % of the
speed of a 100 um whirl at 96 rev/s -- enough to smear the Poincare section into a cloud read as "chaos".

:func:`smoothed_velocity` is instead the first derivative of a local polynomial fitted by least squares
(Savitzky & Golay 1964, Anal. Chem. 36, 1627): degree :data:`DEGREE`, a window of N = 2m + 1 samples
spanning :data:`WINDOW_PERIODS` of the period of the orbit's dominant frequency f_d (the largest peak of the
spectrum of D_Y + i D_Z).  Its amplitude response (measured for N = 117 at 50 us, f_d = 93 Hz) is 0.9996 at
f_d, 0.98 at 2 f_d, 0.85 at 3 f_d and 0.50 at 4 f_d: a loop of a k-period orbit, a torus, a chaotic flow
(all slower than or near f_d) and their first harmonics pass; what is faster (the ball-pass jitter of a
cage, probe noise) is removed.

Noise gain: for white position noise of standard deviation s the velocity noise is
s x G with G = sqrt(sum_k c_k^2) [1/s], c_k the derivative weights (:func:`noise_gain`);
for central differences G = 1 / (sqrt 2 dt).  At the benchmark's sampling (dt = 50 us, f_d = 93 Hz:
N = 117) G = 240 /s against 14 142 /s for central differences: 59 times less velocity noise
(tests/analysis/test_position_only.py measures it on white noise, and the bias on a sinusoid at f_d and
2 f_d).  Degree and window were chosen on the classifier benchmark: degree 4 with a window of half the
period passes it too, but loses 0.5 % of the velocity at f_d (a clean orbit's section moves by more than
the 0.2 % tests/analysis/test_analysis.py allows); degree 6 has the same noise gain and a flat passband.
"""

from __future__ import annotations

import numpy as np

from hsbearing.analysis.spectrum import whirl_frequency

__all__ = ["smoothed_velocity", "velocity_window", "noise_gain", "DEGREE", "WINDOW_PERIODS", "method_text"]

#: Degree of the local polynomial.
DEGREE = 6
#: The window spans this fraction of the period of the orbit's dominant frequency.
WINDOW_PERIODS = 0.55
#: Smallest and largest window [samples].
MIN_WINDOW, MAX_WINDOW = 9, 401


def velocity_window(dt: float, f_dominant: float, n: int) -> int:
    """Odd window length N [samples] spanning WINDOW_PERIODS / |f_dominant|.

    Bounded by [MIN_WINDOW, MAX_WINDOW] and by a third of the samples; MIN_WINDOW when f_d is unknown
    (NaN or 0).
    """
    fd = abs(float(f_dominant)) if np.isfinite(f_dominant) else 0.0
    N = int(round(WINDOW_PERIODS / (fd * dt))) if fd > 0 and dt > 0 else MIN_WINDOW
    N = max(MIN_WINDOW, min(N, MAX_WINDOW, max(n // 3, MIN_WINDOW)))
    return N if N % 2 else N - 1


def _weights(N: int, dt: float) -> np.ndarray:
    from scipy.signal import savgol_coeffs

    return savgol_coeffs(N, DEGREE, deriv=1, delta=dt, use="dot")


def noise_gain(N: int, dt: float) -> float:
    """Velocity noise per unit white position noise [1/s] of the centre weights: sqrt(sum c_k^2)."""
    return float(np.sqrt(np.sum(_weights(N, dt) ** 2)))


def _uniform(t):
    dt = np.diff(t)
    return bool(dt.size) and float(np.ptp(dt)) <= 1e-6 * float(np.mean(dt))


def smoothed_velocity(t, y, z) -> tuple[np.ndarray, np.ndarray, dict]:
    """Velocities (V_Y, V_Z) [m/s] from positions (D_Y, D_Z) [m] at times ``t`` [s], and how they were made.

    Local-polynomial (Savitzky-Golay) derivative, window from :func:`velocity_window`; the ends use the
    polynomial fitted to the first/last window (scipy ``mode="interp"``).  Non-uniform ``t`` is resampled
    linearly on a uniform grid and the result interpolated back.  Fewer than MIN_WINDOW samples: NaN.
    The returned dict holds ``method``, ``window`` [samples], ``dt`` [s], ``dominant_frequency`` [Hz],
    ``noise_gain`` [1/s] and ``central_difference_gain`` [1/s].
    """
    from scipy.signal import savgol_filter

    t = np.asarray(t, float)
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    info = {"method": "local polynomial (Savitzky-Golay) derivative", "degree": DEGREE, "window": 0,
            "dt": float("nan"), "dominant_frequency": float("nan"), "noise_gain": float("nan"),
            "central_difference_gain": float("nan")}
    ok = np.isfinite(t) & np.isfinite(y) & np.isfinite(z)
    vy = np.full_like(y, np.nan)
    vz = np.full_like(z, np.nan)
    if ok.sum() < MIN_WINDOW:
        return vy, vz, info
    tt, yy, zz = t[ok], y[ok], z[ok]
    uniform = _uniform(tt)
    if not uniform:
        tu = np.linspace(tt[0], tt[-1], tt.size)
        yu, zu = np.interp(tu, tt, yy), np.interp(tu, tt, zz)
    else:
        tu, yu, zu = tt, yy, zz
    dt = (tu[-1] - tu[0]) / (tu.size - 1)
    fd = whirl_frequency(tu, yu, zu)
    N = velocity_window(dt, fd, tu.size)
    dy = savgol_filter(yu, N, DEGREE, deriv=1, delta=dt, mode="interp")
    dz = savgol_filter(zu, N, DEGREE, deriv=1, delta=dt, mode="interp")
    if not uniform:
        dy, dz = np.interp(tt, tu, dy), np.interp(tt, tu, dz)
    vy[ok], vz[ok] = dy, dz
    info.update(window=int(N), dt=float(dt), dominant_frequency=float(fd), noise_gain=noise_gain(N, dt),
                central_difference_gain=float(1 / (np.sqrt(2) * dt)))
    return vy, vz, info


def method_text(info: dict) -> str:
    """One line for ``attrs["cage_velocity_source"]``."""
    if not info.get("window"):
        return "estimated from the positions: too few samples"
    return (f"estimated from the positions: {info['method']}, degree {info['degree']}, window {info['window']} samples "
            f"({info['window'] * info['dt'] * 1e3:.3g} ms, {WINDOW_PERIODS:g} period of the dominant "
            f"{abs(info['dominant_frequency']):.4g} Hz); white position noise s gives velocity noise "
            f"{info['noise_gain']:.4g} s /s (central differences: {info['central_difference_gain']:.4g} s /s)")
