"""Dominant whirl frequency of a planar motion (FFT peak): used by the orbit summary and the classifier,
in a module of its own so that neither imports the other (no import circles)."""

from __future__ import annotations

import numpy as np

__all__ = ["whirl_frequency"]


def whirl_frequency(t, y, z) -> float:
    """Dominant (signed) frequency [Hz] of the planar motion (y, z) sampled at times ``t`` [s].

    Resamples to a uniform grid if needed, removes the mean, applies a Hann
    window and refines the largest non-zero FFT peak of y + i z by a parabola
    through the log magnitudes.  NaN if fewer than 16 samples.
    """
    t = np.asarray(t, float)
    if len(t) < 16 or not np.all(np.isfinite(y)) or not np.all(np.isfinite(z)):
        return float("nan")
    dt = np.diff(t)
    if np.ptp(dt) > 1e-6 * np.mean(dt):
        tu = np.linspace(t[0], t[-1], len(t))
        y, z, t = np.interp(tu, t, y), np.interp(tu, t, z), tu
    h = (t[-1] - t[0]) / (len(t) - 1)
    s = (np.asarray(y) - np.mean(y)) + 1j * (np.asarray(z) - np.mean(z))
    n = len(s)
    X = np.abs(np.fft.fft(s * np.hanning(n)))
    f = np.fft.fftfreq(n, h)
    X[0] = 0.0
    k = int(np.argmax(X))
    if X[k] == 0.0:
        return 0.0
    km, kp = (k - 1) % n, (k + 1) % n
    a, b, c = np.log(X[km] + 1e-300), np.log(X[k] + 1e-300), np.log(X[kp] + 1e-300)
    den = a - 2 * b + c
    delta = 0.5 * (a - c) / den if den < 0 else 0.0
    return float(f[k] + delta / (n * h))
