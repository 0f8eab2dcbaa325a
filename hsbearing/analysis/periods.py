"""Period classification of a Poincare section (the section classifier; the classification of the whole cage
motion -- growth, still cage, whirl lock, sub-labels -- is :mod:`hsbearing.analysis.whirl`): "1 period", "k periods", "quasi-periodic", "chaos".

The criteria (thresholds justified in docs/analysis.md):

1. **Normalisation.**  Each coordinate of the section points is divided by the
   peak-to-peak extent of the attractor in that coordinate (``scale``; from
   the continuous orbit ``signal`` when given, else from the points).
2. **Periodicity (cluster test).**  The smallest k (1 <= k <= ``kmax``, at
   least 4 points per cluster) such that every point of each residue class
   {p_r, p_{r+k}, p_{r+2k}, ...} lies within ``tol`` of the class median ->
   ``"1 period"`` / ``"k periods"``.  Points that repeat in order after k
   sections are exactly a period-k orbit of the section map; a slow drift
   (quasi-periodic motion close to a resonance) spreads the classes and fails
   the test.  If the test fails on all points but passes on the last half, the
   motion is still converging to the periodic orbit: the label is the same,
   with reduced confidence.
3. **Aperiodic sections** (at least ``n_min_aperiodic`` points):
   the largest Lyapunov exponent of the section map [2] > ``lyap_threshold``
   (0.15 per section) -> ``"chaos"``; else the median local thickness [4]
   (smaller/larger principal axis of neighbourhoods of max(6, n/10) points)
   > ``thickness_threshold`` (0.45: an irregular scatter, neither points nor
   a curve -- the "disorderly" section of Zhang et al. 2016) -> ``"chaos"`` with
   confidence 0.4 (0.5 if the correlation dimension [3] also exceeds 1.6);
   else (points on curves, no divergence) -> ``"quasi-periodic"``.  With at least ``n_01`` (400) points
   the Gottwald-Melbourne 0-1 test [1] (K > 0.5 chaotic) is a second opinion
   that raises or lowers the confidence; on shorter series it reads
   quasi-periodic sections as chaotic (measured, docs/analysis.md), so it is
   only reported.
4. **Supporting detail** (reported, not deciding): a closed-curve ratio
   (length of the polygon through the points sorted by angle about their
   centroid / perimeter of their convex hull; about 1 for a curve around the
   centroid, >> 1 for a cloud).
5. Fewer than ``n_min`` points, or an aperiodic section with fewer than
   ``n_min_aperiodic`` points -> ``"undetermined"`` with the reason.

References
----------
[1] Gottwald G. A., Melbourne I., "On the implementation of the 0-1 test for
    chaos", SIAM J. Appl. Dyn. Syst. 8 (2009) 129-145, Sec. 3 (Eqs. 3.1-3.6,
    correlation method with the oscillatory term removed).
[2] Rosenstein M. T., Collins J. J., De Luca C. J., "A practical method for
    calculating largest Lyapunov exponents from small data sets", Physica D 65
    (1993) 117-134, Eqs. 5-8 (mean log divergence of nearest neighbours).
[3] Grassberger P., Procaccia I., "Characterization of strange attractors",
    Phys. Rev. Lett. 50 (1983) 346-349 (correlation sum C(r) ~ r^D2).
[4] Fukunaga K., Olsen D. R., "An algorithm for finding intrinsic
    dimensionality of data", IEEE Trans. Computers C-20 (1971) 176-183 (local
    principal components).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "LABELS",
    "DEFAULTS",
    "classify",
    "period_label",
    "periodicity",
    "zero_one_test",
    "lyapunov_exponent",
    "correlation_dimension",
    "closed_curve_ratio",
    "local_thickness",
    "scattered_groups",
    "rotation_number",
    "circle_centre",
    "rotation",
    "false_nearest_neighbours",
    "embedding_dimension",
]

#: Closed vocabulary of the labels (``"k periods"`` stands for any k >= 2).
LABELS = ("1 period", "k periods", "quasi-periodic", "chaos", "undetermined")

#: Default thresholds (see docs/analysis.md for their justification).
DEFAULTS = dict(
    tol=0.02,  # cluster radius / attractor peak-to-peak
    kmax=16,  # largest period searched
    n_min=6,  # fewest section points for any label
    n_min_aperiodic=40,  # fewest points to separate quasi-periodic from chaos
    modulation_tol=0.06,  # one cluster within 6 % of the orbit: "1 period" with a modulation of that amplitude
    separation=4.0,  # k >= 2 clusters: class medians at least 4 spreads apart
    min_turns=1.0,  # quasi-periodic: at least one full turn round the invariant curve over the window
    same_sense=0.9,  # invariant curve: at least 90 % of the steps turn the same way
    max_gap=0.25,  # closed curve: no angular gap larger than a quarter turn between the sorted points
    thickness_threshold=0.45,  # median local thickness above which the section is a cloud, not curves
    lyap_threshold=0.1,  # chaos needs a divergence rate > 0.1 per section (in the FNN embedding) ...
    k01_threshold=0.5,  # ... and the 0-1 test K > 0.5
    fnn_threshold=0.1,  # embedding dimension: false-nearest-neighbour fraction < 10 %
    m_max=5,  # largest embedding dimension tried
)


def period_label(k: int) -> str:
    """``"1 period"`` or ``"k periods"`` (the wording of Zhang et al. 2016, Tables 3-5)."""
    return "1 period" if k == 1 else f"{k} periods"


def _normalise(points, signal=None, scale=None) -> np.ndarray:
    P = np.asarray(points, dtype=float)
    if P.ndim == 1:
        P = P[:, None]
    P = P[np.all(np.isfinite(P), axis=1)]
    if scale is None:
        ref = P
        if signal is not None:
            S = np.asarray(signal, dtype=float)
            S = S[:, None] if S.ndim == 1 else S
            if S.shape[1] == P.shape[1]:
                S = S[np.all(np.isfinite(S), axis=1)]
                if len(S):
                    ref = S
        scale = np.ptp(ref, axis=0) if len(ref) else np.ones(P.shape[1])
        if len(P):
            scale = np.maximum(scale, 1e-9 * np.max(np.abs(P), axis=0))
    scale = np.broadcast_to(np.asarray(scale, dtype=float), (P.shape[1],)).copy()
    scale[~(scale > 0)] = 1.0
    if len(P) == 0:
        return P
    return (P - P.mean(axis=0)) / scale


#: Quantile of the point-to-median distances taken as a cluster's spread (robust to a few noisy crossings).
SPREAD_QUANTILE = 0.95


def _class_spread(Q, k: int) -> tuple[float, np.ndarray]:
    """Spread of the residue classes mod k (the 95th percentile of the point-to-class-median distances), and
    the k class medians."""
    meds = np.array([np.median(Q[r::k], axis=0) for r in range(k)])
    d = np.concatenate([np.linalg.norm(Q[r::k] - meds[r], axis=1) for r in range(k)])
    return float(np.quantile(d, SPREAD_QUANTILE)), meds


def periodicity(Q, tol: float = DEFAULTS["tol"], kmax: int = DEFAULTS["kmax"], min_per_cluster: int = 4,
                separation: float = DEFAULTS["separation"]):
    """Smallest period k of normalised section points ``Q`` (cluster test), or None.

    k passes when every point lies within ``tol`` of the median of its residue class (points r, r+k, r+2k,
    ...) and, for k >= 2, the k class medians are at least ``separation`` times the largest class spread
    apart (k clusters, not one smeared cluster cut into k interleaved pieces).  Returns ``(k, spread,
    sep)`` with ``sep`` the smallest median distance / spread (inf for k = 1), or ``(None, best_spread,
    None)`` with the smallest spread over the k tried.
    """
    Q = np.asarray(Q, dtype=float)
    n = len(Q)
    best = np.inf
    for k in range(1, min(kmax, n // min_per_cluster) + 1):
        spread, meds = _class_spread(Q, k)
        best = min(best, spread)
        if spread > tol:
            continue
        if k == 1:
            return 1, spread, float("inf")
        d = np.linalg.norm(meds[:, None, :] - meds[None, :, :], axis=-1)[np.triu_indices(k, 1)]
        sep = float(d.min() / spread) if spread > 0 else float("inf")
        if sep >= separation:
            return k, spread, sep
    return None, best, None


def scattered_groups(Q, kmax: int = DEFAULTS["kmax"], separation: float = 3.0, min_per_cluster: int = 3):
    """Smallest k >= 2 whose residue classes form separated groups, or None.

    Groups are separated when the smallest distance between class medians is
    at least ``separation`` times the largest class spread.  Used only to word
    the reason of an irregular section ("scatter around k groups").
    """
    Q = np.asarray(Q, dtype=float)
    for k in range(2, min(kmax, len(Q) // min_per_cluster) + 1):
        spread, meds = _class_spread(Q, k)
        d = np.linalg.norm(meds[:, None, :] - meds[None, :, :], axis=-1)[np.triu_indices(k, 1)]
        if d.min() >= separation * spread:
            return k, spread
    return None


def local_thickness(Q, m: int | None = None, n_max: int = 1500) -> float:
    """Median local thickness of a point set: smaller / larger principal axis of each point's neighbourhood.

    Local principal-component estimate of the intrinsic dimension (Fukunaga &
    Olsen [4]): each point and its ``m`` nearest neighbours (default
    max(6, n/10), so the neighbourhood covers a fixed share of the set) are
    reduced to their singular values s_1 >= s_2; the median of s_2 / s_1 is
    about 0 for points on curves (a closed invariant curve, arcs, the logistic
    parabola) and about 0.6-0.8 for a scattered cloud.
    """
    Q = np.asarray(Q, dtype=float)[-n_max:]
    n = len(Q)
    if n < 8 or Q.shape[1] < 2:
        return float("nan")
    m = m or max(6, int(round(0.1 * n)))
    m = min(m, n - 1)
    d2 = np.sum((Q[:, None, :] - Q[None, :, :]) ** 2, axis=-1)
    idx = np.argsort(d2, axis=1)[:, : m + 1]
    N = Q[idx]  # (n, m + 1, d)
    N = N - N.mean(axis=1, keepdims=True)
    sv = np.linalg.svd(N, compute_uv=False)  # (n, d), descending
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.where(sv[:, 0] > 0, sv[:, 1] / sv[:, 0], 0.0)
    return float(np.median(ratio))


def zero_one_test(x, n_c: int = 100, seed: int = 0, n_max: int = 2000) -> float:
    """Gottwald-Melbourne 0-1 test for chaos, correlation method [1]: K in about [0, 1].

    Parameters
    ----------
    x : (N,) array_like
        Scalar observable of a map (here one coordinate of the Poincare points).
    n_c : int
        Number of random frequencies c in (pi/5, 4 pi/5) ([1], Sec. 3.2).
    seed : int
        Seed of the frequencies (the result is reproducible).
    n_max : int
        Only the last ``n_max`` values are used (cost O(n_c N^2 / 10)).

    Returns
    -------
    float
        median over c of K_c = corr(n, D_c(n)), n = 1..N/10.
    """
    phi = np.asarray(x, dtype=float)
    phi = phi[np.isfinite(phi)][-n_max:]
    N = len(phi)
    if N < 20:
        return float("nan")
    phi = phi - phi.mean()  # removes the oscillatory term (E phi)^2 (1 - cos nc)/(1 - cos c), [1] Eq. 3.5
    rng = np.random.default_rng(seed)
    c = rng.uniform(np.pi / 5, 4 * np.pi / 5, n_c)
    j = np.arange(1, N + 1)
    arg = np.outer(c, j)
    p = np.cumsum(phi * np.cos(arg), axis=1)  # [1] Eq. 3.1
    q = np.cumsum(phi * np.sin(arg), axis=1)
    n_cut = max(N // 10, 3)  # [1] Sec. 3.1: n <= N/10
    M = np.empty((n_c, n_cut))
    for n in range(1, n_cut + 1):  # mean-square displacement, [1] Eq. 3.2
        dp = p[:, n:] - p[:, :-n]
        dq = q[:, n:] - q[:, :-n]
        M[:, n - 1] = np.mean(dp * dp + dq * dq, axis=1)
    xi = np.arange(1, n_cut + 1, dtype=float)
    xi -= xi.mean()
    Dm = M - M.mean(axis=1, keepdims=True)
    den = np.sqrt(np.sum(xi**2) * np.sum(Dm**2, axis=1))
    with np.errstate(invalid="ignore", divide="ignore"):
        Kc = np.where(den > 0, Dm @ xi / den, 0.0)  # [1] Eq. 3.6, K_c = corr(xi, D_c)
    return float(np.median(Kc))


def _embed(Q, m: int) -> np.ndarray:
    n = len(Q) - m + 1
    return np.hstack([Q[i : i + n] for i in range(m)])


def lyapunov_exponent(Q, m: int = 2, steps: int = 4, n_max: int = 1500) -> float:
    """Largest Lyapunov exponent of a section map [1/section] (Rosenstein et al. [2]).

    Each point (delay-embedded with ``m`` consecutive section points) is paired
    with its nearest neighbour; the mean log distance of the pairs' images
    after 1..``steps`` sections is fitted by a straight line ([2], Eqs. 5-8).
    Step 0 is left out of the fit: with noisy data the nearest neighbour is
    biased close and the first step would read the noise as divergence.
    """
    Q = np.asarray(Q, dtype=float)[-n_max:]
    X = _embed(Q, m)
    M = len(X) - steps
    if M < 10:
        return float("nan")
    A = X[:M]
    d2 = np.sum(A * A, axis=1)[:, None] + np.sum(A * A, axis=1)[None, :] - 2.0 * A @ A.T
    np.fill_diagonal(d2, np.inf)
    nn = np.argmin(d2, axis=1)
    i = np.arange(M)
    logs = []
    for k in range(1, steps + 1):
        d = np.linalg.norm(X[i + k] - X[nn + k], axis=1)
        d = d[d > 0]
        logs.append(np.mean(np.log(d)) if d.size else np.nan)
    y = np.asarray(logs)
    k = np.arange(1, steps + 1, dtype=float)
    ok = np.isfinite(y)
    if ok.sum() < 2:
        return float("nan")
    return float(np.polyfit(k[ok], y[ok], 1)[0])  # [2], Eq. 8: slope of <ln d_j(i)> vs i


def correlation_dimension(Q, n_max: int = 1500) -> float:
    """Correlation dimension D2 of a point set (Grassberger-Procaccia [3]): slope of log C(r) vs log r.

    The fit uses the radii where the correlation sum C(r) lies between
    max(20 / n_pairs, 1e-3) and 0.2 (the scaling region for small sets).
    """
    Q = np.asarray(Q, dtype=float)[-n_max:]
    n = len(Q)
    if n < 20:
        return float("nan")
    iu = np.triu_indices(n, 1)
    d = np.sqrt(np.maximum(np.sum((Q[:, None, :] - Q[None, :, :]) ** 2, axis=-1)[iu], 0.0))
    d = np.sort(d[d > 0])
    if d.size < 20:
        return float("nan")
    npairs = len(iu[0])
    lo = max(20.0 / npairs, 1e-3)
    C = np.arange(1, d.size + 1) / npairs  # C(r = d_k) = k / n_pairs   [3]
    sel = (C >= lo) & (C <= 0.2)
    if sel.sum() < 5:
        return float("nan")
    return float(np.polyfit(np.log(d[sel]), np.log(C[sel]), 1)[0])


def closed_curve_ratio(Q) -> float:
    """Length of the polygon through the points sorted by angle about their centroid / convex-hull perimeter.

    About 1 when the points lie on a closed curve around their centroid (the
    "closed curve formed by Poincare points" of a quasi-periodic motion,
    Zhang et al. 2016 Sec. 4); much larger than 1 for a scattered cloud.
    """
    Q = np.asarray(Q, dtype=float)
    if len(Q) < 8 or Q.shape[1] != 2:
        return float("nan")
    from scipy.spatial import ConvexHull, QhullError

    c = Q.mean(axis=0)
    order = np.argsort(np.arctan2(Q[:, 1] - c[1], Q[:, 0] - c[0]))
    S = Q[order]
    L = float(np.sum(np.linalg.norm(np.diff(np.vstack([S, S[:1]]), axis=0), axis=1)))
    try:
        hull = ConvexHull(Q)
    except QhullError:
        return float("nan")
    return L / hull.area if hull.area > 0 else float("nan")  # 2-D hull: .area is the perimeter


def circle_centre(Q) -> np.ndarray:
    """Centre of the least-squares circle through 2-D points (Kasa's algebraic fit), or their centroid.

    Kasa I. D., "A circle fitting procedure and its error analysis", IEEE Trans. Instrum. Meas. 25 (1976)
    8-14: minimise sum (x^2 + y^2 + D x + E y + F)^2, linear in (D, E, F).  For points on an arc the
    centre is the arc's centre of curvature, not the centroid of the points (which lies on the chord side
    and makes an arc look like a whole turn); for points on a closed curve both are inside the curve.
    """
    Q = np.asarray(Q, dtype=float)
    c0 = Q.mean(axis=0)
    if len(Q) < 3 or Q.shape[1] != 2:
        return c0
    X = Q - c0
    A = np.column_stack([X, np.ones(len(X))])
    b = -np.sum(X * X, axis=1)
    sol, *_ = np.linalg.lstsq(A, b, rcond=None)
    c = -0.5 * sol[:2]
    size = float(np.max(np.ptp(X, axis=0))) or 1.0
    if not np.all(np.isfinite(c)) or np.hypot(*c) > 50.0 * size:  # (nearly) collinear points: no circle
        return c0
    return c0 + c


def rotation(Q, centre=None) -> dict:
    """Rotation of a sequence of 2-D points about a centre: total turns, mean turn per step, order, coverage.

    The angle of each point about ``centre`` (default :func:`circle_centre`) is differenced along the
    sequence, each step wrapped to (-1/2, 1/2] turn, and summed (the unwrapped phase).  Returns
    ``turns`` (|total| [turns]), ``rho`` (signed mean turn per step), ``rho_sd`` (its standard error from
    the scatter of the steps [turns]), ``same_sense`` (fraction of the steps turning the majority way),
    ``largest_gap`` (largest angular gap between the sorted angles [turns]; small for points all around a
    closed curve, large for an arc).  For an invariant circle of a quasi-periodic section the steps all turn
    the same way (a circle homeomorphism, Arnold 1983, Sec. 11) and ``rho`` is its rotation number.
    """
    Q = np.asarray(Q, dtype=float)
    out = {"turns": float("nan"), "rho": float("nan"), "rho_sd": float("nan"), "same_sense": float("nan"),
           "largest_gap": float("nan")}
    if len(Q) < 3 or Q.shape[1] != 2:
        return out
    c = circle_centre(Q) if centre is None else np.asarray(centre, float)
    ang = np.arctan2(Q[:, 1] - c[1], Q[:, 0] - c[0]) / (2 * np.pi)
    d = np.diff(ang)
    d = d - np.round(d)  # each step wrapped to (-1/2, 1/2] turn
    tot = float(np.sum(d))
    sgn = 1.0 if tot >= 0 else -1.0
    srt = np.sort(ang % 1.0)
    gaps = np.diff(np.concatenate([srt, srt[:1] + 1.0]))
    out.update(turns=abs(tot), rho=float(np.mean(d)), rho_sd=float(np.std(d) / math.sqrt(len(d))),
               same_sense=float(np.mean(sgn * d > 0)), largest_gap=float(np.max(gaps)))
    return out


def rotation_number(Q) -> float:
    """Mean rotation per section of points circling their curve's centre, folded to [0, 0.5] [turns].

    The centre is the least-squares circle centre (:func:`circle_centre`), not the centroid of the points
    (on an arc the centroid lies near the chord and the rotation read about it is several times too large);
    the angle is unwrapped along the sequence (:func:`rotation`) and the mean increment, taken modulo 1 and
    folded (rho and 1 - rho are the same rotation seen from the other side), is the rotation number.  For
    the cage-revolution section of a circular whirl it is the whirl/cage speed ratio modulo 1, folded.
    """
    r = rotation(Q)
    if not math.isfinite(r["rho"]):
        return float("nan")
    rho = r["rho"] % 1.0
    return float(min(rho, 1.0 - rho))


def false_nearest_neighbours(x, m_max: int = 5, r_tol: float = 10.0, a_tol: float = 2.0) -> np.ndarray:
    """Fraction of false nearest neighbours of a scalar series in delay embeddings of dimension 1..m_max.

    Kennel M. B., Brown R., Abarbanel H. D. I., "Determining embedding dimension for phase-space
    reconstruction using a geometrical construction", Phys. Rev. A 45 (1992) 3403-3411, Eqs. 4-5: the
    nearest neighbour of a point in dimension m is false when adding the (m+1)-th delay coordinate moves it
    away by more than ``r_tol`` times their distance, or by more than ``a_tol`` times the attractor size
    (standard deviation of x).  Deterministic low-dimensional data reach a small fraction at the embedding
    dimension; noise does not.
    """
    x = np.asarray(x, dtype=float)
    x = x[np.isfinite(x)]
    RA = float(np.std(x)) or 1.0
    out = np.full(m_max, np.nan)
    for m in range(1, m_max + 1):
        n = len(x) - m
        if n < 10:
            break
        X = np.column_stack([x[i : i + n] for i in range(m)])
        nxt = x[m : m + n]
        d2 = np.sum((X[:, None, :] - X[None, :, :]) ** 2, axis=-1)
        np.fill_diagonal(d2, np.inf)
        j = np.argmin(d2, axis=1)
        dm = np.sqrt(d2[np.arange(n), j])
        dx = np.abs(nxt - nxt[j])
        with np.errstate(divide="ignore", invalid="ignore"):
            false = (dx > r_tol * dm) | (np.sqrt(dm**2 + dx**2) > a_tol * RA)
        out[m - 1] = float(np.mean(false))
    return out


def embedding_dimension(x, m_max: int = 5, threshold: float = 0.1) -> int | None:
    """Smallest delay-embedding dimension whose false-nearest-neighbour fraction is below ``threshold``."""
    f = false_nearest_neighbours(x, m_max)
    ok = np.nonzero(np.isfinite(f) & (f < threshold))[0]
    return int(ok[0]) + 1 if ok.size else None


def _delay_lyapunov(x, m: int, steps: int = 4, n_max: int = 1500) -> float:
    """Largest Lyapunov exponent [1/section] of a scalar series in an m-dimensional delay embedding [2]."""
    x = np.asarray(x, dtype=float)[-n_max:]
    return lyapunov_exponent(x[:, None], m=m, steps=steps, n_max=n_max)


def _is_curve_rotation(Q, min_turns, same_sense, max_gap, thickness_threshold) -> tuple[bool, dict]:
    """Points on one closed curve visited in a consistent rotation (an invariant circle) -- and how far round."""
    r = rotation(Q)
    tau = local_thickness(Q) if len(Q) >= 8 else float("nan")
    r["local_thickness"] = tau
    curve = (math.isfinite(tau) and tau <= thickness_threshold and math.isfinite(r["same_sense"])
             and r["same_sense"] >= same_sense)
    r["curve"] = bool(curve)
    r["closed"] = bool(curve and r["turns"] >= min_turns and r["largest_gap"] <= max_gap)
    return r["closed"], r


def classify(points, signal=None, *, scale=None, tol=DEFAULTS["tol"], kmax=DEFAULTS["kmax"],
             n_min=DEFAULTS["n_min"], n_min_aperiodic=DEFAULTS["n_min_aperiodic"],
             modulation_tol=DEFAULTS["modulation_tol"], separation=DEFAULTS["separation"], min_turns=DEFAULTS["min_turns"],
             same_sense=DEFAULTS["same_sense"], max_gap=DEFAULTS["max_gap"],
             lyap_threshold=DEFAULTS["lyap_threshold"], thickness_threshold=DEFAULTS["thickness_threshold"],
             fnn_threshold=DEFAULTS["fnn_threshold"], m_max=DEFAULTS["m_max"],
             k01_threshold=DEFAULTS["k01_threshold"], seed=0):
    """Classify a Poincare section (criteria in the module docstring and docs/analysis.md).

    Parameters
    ----------
    points : (n, d) array_like
        Section points in order of the crossings (e.g. D_Y [m], V_Y [m/s]).
    signal : (m, d) array_like, optional
        The continuous trajectory in the same coordinates; its peak-to-peak
        extent sets the scale of the tolerance.  Without it (and without
        ``scale``) the points' own extent is used, which cannot tell a tight
        noisy single cluster from a cloud: pass one of them for real runs.
    scale : (d,) array_like, optional
        Peak-to-peak attractor extent per coordinate (overrides ``signal``).
    tol : float
        Cluster radius as a fraction of the extent (default 0.02).

    Returns
    -------
    label : str
        ``"1 period"``, ``"k periods"`` (k an integer), ``"quasi-periodic"``,
        ``"chaos"`` or ``"undetermined"``.
    confidence : float
        In [0, 1] (0 for "undetermined").
    details : dict
        Indicators: ``n_points``, ``period``, ``spread``, ``separation``, ``turns``, ``rotation_number``,
        ``same_sense``, ``largest_gap``, ``k01``, ``embedding_dimension``, ``lyapunov``,
        ``correlation_dimension``, ``local_thickness``, ``closed_curve_ratio``, ``sections_per_turn``,
        ``kind`` (a one-word reading: periodic, converging, invariant-curve, drifting-arc, chaotic,
        irregular, too-few-points) and ``reason``.
    """
    Q = _normalise(points, signal, scale)
    n = len(Q)
    det: dict = {"n_points": n, "tol": tol, "period": None, "spread": None, "separation": None, "k01": None,
                 "lyapunov": None, "embedding_dimension": None, "correlation_dimension": None,
                 "local_thickness": None, "closed_curve_ratio": None, "groups": None, "rotation_number": None,
                 "turns": None, "same_sense": None, "largest_gap": None, "sections_per_turn": None, "islands": None,
                 "kind": "", "reason": ""}
    if n < n_min:
        det["kind"] = "too-few-points"
        det["reason"] = (f"only {n} Poincare section point{'' if n == 1 else 's'} (need >= {n_min}); "
                         "simulate longer")
        return "undetermined", 0.0, det
    # --- 1. periodic: k clusters repeated in order, each within tol, separated by >= `separation` spreads
    k, spread, sep = periodicity(Q, tol, kmax, separation=separation)
    converging = False
    if k is None and n >= 2 * n_min:
        k2, spread2, sep2 = periodicity(Q[n // 2 :], tol, kmax, separation=separation)
        if k2 is not None:
            k, spread, sep, converging = k2, spread2, sep2, True
    if k is not None:
        n_used = n - n // 2 if converging else n
        det.update(period=k, spread=spread, separation=sep)
        conf = (1.0 - 0.5 * spread / tol) * min(1.0, np.sqrt((n_used / k) / 10.0))
        if converging:
            conf *= 0.8
            det["kind"] = "converging"
            det["reason"] = "periodic on the last half of the section only (transient still decaying)"
        else:
            det["kind"] = "periodic"
            det["reason"] = f"all points within {spread:.3g} (tol {tol}) of {k} cluster(s) repeated in order"
            if k > 1:
                det["reason"] += f", clusters {sep:.1f} spreads apart"
        return period_label(k), float(round(conf, 3)), det
    det["spread"] = spread
    det["closed_curve_ratio"] = closed_curve_ratio(Q) if Q.shape[1] == 2 else None
    s1 = _class_spread(Q, 1)[0]
    if s1 <= modulation_tol:
        # one cluster, wider than the resolution tol but small against the orbit: one loop carrying a
        # modulation the section does not resolve into a structure (e.g. the ball-pass ripple of V_Y)
        det.update(period=1, spread=s1, kind="modulated")
        conf = 0.5 * (1.0 - 0.5 * s1 / modulation_tol) * min(1.0, np.sqrt(n / 10.0))
        det["reason"] = (f"one cluster of spread {100 * s1:.1f} % of the orbit (> the {100 * tol:g} % resolution, "
                         f"<= {100 * modulation_tol:g} %): one loop with a modulation of that amplitude")
        return "1 period", float(round(conf, 3)), det
    if n < n_min_aperiodic:
        det["kind"] = "too-few-points"
        det["reason"] = (f"not periodic (k <= {kmax}), but only {n} section points: need >= {n_min_aperiodic} "
                         "to tell quasi-periodic from chaos; simulate longer")
        return "undetermined", 0.0, det
    # --- 2. an invariant closed curve (or k islands of curves) visited in a consistent rotation: quasi-periodic
    if Q.shape[1] == 2:
        best = None
        for kk in range(1, 5):
            if n // kk < n_min_aperiodic // 2:
                break
            rots = [_is_curve_rotation(Q[r::kk], min_turns, same_sense, max_gap, thickness_threshold) for r in range(kk)]
            if all(ok for ok, _ in rots):
                best = (kk, rots)
                break
            if kk == 1:
                first = rots[0][1]
        r1 = first if best is None else best[1][0][1]
        det.update(turns=r1["turns"], same_sense=r1["same_sense"], largest_gap=r1["largest_gap"],
                   local_thickness=r1["local_thickness"])
        if best is not None:
            kk, rots = best
            r = rots[0][1]
            rho = r["rho"] % 1.0
            det.update(rotation_number=float(min(rho, 1.0 - rho)), islands=kk,
                       turns=min(rr["turns"] for _, rr in rots))
            conf = 0.6 + 0.4 * min(1.0, det["turns"] / 5.0)
            conf *= 1.0 - 0.5 * r["local_thickness"] / thickness_threshold
            conf *= min(1.0, math.sqrt(n / 100.0))
            det["kind"] = "invariant-curve"
            where = "one closed curve" if kk == 1 else f"{kk} closed curves visited in turn"
            det["reason"] = (f"aperiodic, points on {where} (local thickness {r['local_thickness']:.2f}), "
                             f"{100 * r['same_sense']:.0f} % of the steps turning the same way, "
                             f"{det['turns']:.1f} turns over the window; rotation number {det['rotation_number']:.3f}")
            return "quasi-periodic", float(round(min(max(conf, 0.0), 1.0), 3)), det
        if r1["curve"] and r1["turns"] < min_turns:
            # one curve, consistent rotation, but not yet round once: a drifting arc (slow drift / locking)
            spt = (n - 1) / r1["turns"] if r1["turns"] > 0 else float("inf")
            det.update(sections_per_turn=spt, kind="drifting-arc")
            det["reason"] = (f"the points drift along an arc ({r1['turns']:.2f} turn of their curve over {n} "
                             f"sections, all steps the same way): quasi-periodic or a slow transient cannot be told "
                             f"apart before one full turn; run ~{max(spt - (n - 1), 0):.0f} more sections")
            return "undetermined", 0.0, det
    # --- 3. chaos only when two independent indicators agree
    x = Q[:, 0]
    groups = scattered_groups(Q, kmax)
    if groups and n // groups[0] >= 20:
        # banded section (k separated bands visited in turn): the band alternation is a period-k component
        # that dominates the 0-1 test's mean-square displacement and fakes determinism in a delay embedding
        # (the next band is always predictable); both indicators read the k-th return map of each band
        kb = groups[0]
        series = [x[r::kb] for r in range(kb)]
    else:
        kb, series = 1, [x]
    K = float(np.mean([zero_one_test(xs, seed=seed) for xs in series]))
    ms = [embedding_dimension(xs, m_max=m_max, threshold=fnn_threshold) for xs in series]
    m = None if any(v is None for v in ms) else max(ms)
    lam = float(np.mean([_delay_lyapunov(xs, m) for xs in series])) / kb if m is not None else float("nan")
    D2 = correlation_dimension(Q)
    tau = det["local_thickness"] if det["local_thickness"] is not None else local_thickness(Q)
    det.update(k01=K, embedding_dimension=m, lyapunov=lam, correlation_dimension=D2, local_thickness=tau)
    chaotic_01 = math.isfinite(K) and K > k01_threshold
    diverging = m is not None and math.isfinite(lam) and lam > lyap_threshold
    if chaotic_01 and diverging:
        det["kind"] = "chaotic"
        conf = 0.5 + 0.25 * min(1.0, (K - k01_threshold) / 0.4) + 0.25 * min(1.0, (lam - lyap_threshold) / 0.3)
        conf *= min(1.0, math.sqrt(n / 100.0))
        det["reason"] = (f"aperiodic; 0-1 test K = {K:.2f} > {k01_threshold} and divergence rate {lam:.3g}/section "
                         f"> {lyap_threshold} in a {m}-dimensional delay embedding (false nearest neighbours)")
        return "chaos", float(round(min(max(conf, 0.0), 1.0), 3)), det
    det["groups"] = groups[0] if groups else None
    det["kind"] = "irregular"
    why = []
    why.append(f"0-1 test K = {K:.2f}" + (" (chaotic)" if chaotic_01 else " (regular)"))
    if m is None:
        why.append(f"no delay embedding up to {m_max} dimensions removes the false neighbours (noise-like)")
    else:
        why.append(f"divergence {lam:.3g}/section in {m} dimensions" + (" (diverging)" if diverging else ""))
    where = f" around {groups[0]} separated groups" if groups else ""
    det["reason"] = (f"aperiodic irregular section{where} (spread {100 * spread:.1f} % of the orbit), neither "
                     f"periodic nor a curve, and the chaos indicators do not agree: " + "; ".join(why) + "; run longer")
    return "undetermined", 0.0, det
