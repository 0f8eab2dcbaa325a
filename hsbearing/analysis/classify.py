"""Period classification of a Poincare section: "1 period", "k periods", "quasi-periodic", "chaos".

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
   a curve -- the "disorderly" section of seed 004) -> ``"chaos"`` with
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
    "DETAILS",
    "classification_detail",
    "cage_instability_index",
]

#: Closed vocabulary of the labels (``"k periods"`` stands for any k >= 2).
LABELS = ("1 period", "k periods", "quasi-periodic", "chaos", "undetermined")

#: Default thresholds (see docs/analysis.md for their justification).
DEFAULTS = dict(
    tol=0.02,  # cluster radius / attractor peak-to-peak
    kmax=16,  # largest period searched
    n_min=6,  # fewest section points for any label
    n_min_aperiodic=40,  # fewest points to separate quasi-periodic from chaos
    lyap_threshold=0.15,  # largest Lyapunov exponent per section > 0.15: chaos
    thickness_threshold=0.45,  # median local thickness above which the section is a cloud, not curves
    d2_cloud=1.6,  # correlation dimension above which a cloud is called area-filling (confidence only)
    n_01=400,  # fewest points for the 0-1 test to count (false "chaos" below, see docs/analysis.md)
    k01_threshold=0.5,  # 0-1 test: K > 0.5 chaotic
)


def period_label(k: int) -> str:
    """``"1 period"`` or ``"k periods"`` (the wording of seed 004, Tables 3-5)."""
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


def _class_spread(Q, k: int) -> tuple[float, np.ndarray]:
    """Largest distance of a point from the median of its residue class mod k, and the k class medians."""
    meds = np.array([np.median(Q[r::k], axis=0) for r in range(k)])
    spread = max(float(np.max(np.linalg.norm(Q[r::k] - meds[r], axis=1))) for r in range(k))
    return spread, meds


def periodicity(Q, tol: float = DEFAULTS["tol"], kmax: int = DEFAULTS["kmax"], min_per_cluster: int = 4):
    """Smallest period k of normalised section points ``Q`` (cluster test), or None.

    Returns ``(k, spread)`` where ``spread`` is the largest distance of a point
    from the median of its residue class (points r, r+k, r+2k, ...), or
    ``(None, best_spread)`` with the smallest such spread over the k tried.
    """
    Q = np.asarray(Q, dtype=float)
    n = len(Q)
    best = np.inf
    for k in range(1, min(kmax, n // min_per_cluster) + 1):
        spread, _ = _class_spread(Q, k)
        best = min(best, spread)
        if spread <= tol:
            return k, spread
    return None, best


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
    seed 004 Sec. 4); much larger than 1 for a scattered cloud.
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


def rotation_number(Q) -> float:
    """Mean rotation per section of points circling their centroid, folded to [0, 0.5] [turns].

    The angle of each point about the centroid is unwrapped along the
    sequence; the mean increment / 2 pi, taken modulo 1 and folded (rho and
    1 - rho are the same rotation seen from the other side), is the rotation
    number of a quasi-periodic section -- for the cage-revolution section of
    a circular whirl, the whirl/cage speed ratio modulo 1, folded.
    """
    Q = np.asarray(Q, dtype=float)
    if len(Q) < 3:
        return float("nan")
    c = Q.mean(axis=0)
    ang = np.unwrap(np.arctan2(Q[:, 1] - c[1], Q[:, 0] - c[0]))
    rho = (np.mean(np.diff(ang)) / (2 * np.pi)) % 1.0
    return float(min(rho, 1.0 - rho))


def classify(points, signal=None, *, scale=None, tol=DEFAULTS["tol"], kmax=DEFAULTS["kmax"],
             n_min=DEFAULTS["n_min"], n_min_aperiodic=DEFAULTS["n_min_aperiodic"],
             lyap_threshold=DEFAULTS["lyap_threshold"], thickness_threshold=DEFAULTS["thickness_threshold"],
             d2_cloud=DEFAULTS["d2_cloud"], n_01=DEFAULTS["n_01"],
             k01_threshold=DEFAULTS["k01_threshold"], seed=0):
    """Classify a Poincare section (criteria in the module docstring).

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
        Indicators: ``n_points``, ``period``, ``spread``, ``k01``,
        ``lyapunov``, ``correlation_dimension``, ``closed_curve_ratio``,
        ``reason``.
    """
    Q = _normalise(points, signal, scale)
    n = len(Q)
    det: dict = {"n_points": n, "tol": tol, "period": None, "spread": None, "k01": None, "lyapunov": None,
                 "correlation_dimension": None, "local_thickness": None, "closed_curve_ratio": None, "groups": None,
                 "rotation_number": None,
                 "reason": ""}
    if n < n_min:
        det["reason"] = f"only {n} Poincare section points (need >= {n_min}); simulate longer"
        return "undetermined", 0.0, det
    k, spread = periodicity(Q, tol, kmax)
    converging = False
    if k is None and n >= 2 * n_min:
        k2, spread2 = periodicity(Q[n // 2 :], tol, kmax)
        if k2 is not None:
            k, spread, converging = k2, spread2, True
    if k is not None:
        n_used = n - n // 2 if converging else n
        det.update(period=k, spread=spread)
        conf = (1.0 - 0.5 * spread / tol) * min(1.0, np.sqrt((n_used / k) / 10.0))
        if converging:
            conf *= 0.8
            det["reason"] = "periodic on the last half of the section only (transient still decaying)"
        else:
            det["reason"] = f"all points within {spread:.3g} (tol {tol}) of {k} cluster(s) repeated in order"
        return period_label(k), float(round(conf, 3)), det
    det["spread"] = spread
    det["closed_curve_ratio"] = closed_curve_ratio(Q) if Q.shape[1] == 2 else None
    if n < n_min_aperiodic:
        det["reason"] = (f"not periodic (k <= {kmax}), but only {n} section points: need >= {n_min_aperiodic} "
                         "to tell quasi-periodic from chaos; simulate longer")
        return "undetermined", 0.0, det
    lam = lyapunov_exponent(Q)
    D2 = correlation_dimension(Q)
    tau = local_thickness(Q)
    K = zero_one_test(Q[:, 0], seed=seed) if n >= n_01 else float("nan")
    det.update(k01=K, lyapunov=lam, correlation_dimension=D2, local_thickness=tau)
    if not np.isfinite(lam) or not np.isfinite(tau):
        det["reason"] = "aperiodic, but the Lyapunov exponent or the local thickness could not be estimated"
        return "undetermined", 0.0, det
    if lam > lyap_threshold:  # exponential divergence of neighbouring section points
        label = "chaos"
        conf = 0.5 + 0.5 * min(1.0, (lam - lyap_threshold) / 0.2)
        det["reason"] = f"aperiodic, largest Lyapunov exponent {lam:.3g}/section > {lyap_threshold}"
    elif tau > thickness_threshold:  # irregular scatter: neither points nor a curve (the seed's "disorderly" map)
        label = "chaos"
        conf = 0.4 + (0.1 if np.isfinite(D2) and D2 > d2_cloud else 0.0)
        groups = scattered_groups(Q, kmax)
        det["groups"] = groups[0] if groups else None
        where = (f"around {groups[0]} separated groups (spread {100 * groups[1]:.1f} % of the orbit > tol "
                 f"{100 * tol:g} %)") if groups else f"(spread {100 * spread:.1f} % of the orbit at best)"
        det["reason"] = (f"aperiodic: irregular scatter {where}, local thickness {tau:.2f} > {thickness_threshold}, "
                         f"Lyapunov {lam:.3g}/section (no measurable divergence)")
    else:
        label = "quasi-periodic"
        conf = 0.5 + 0.5 * (1.0 - min(max(lam, 0.0), lyap_threshold) / lyap_threshold)
        conf *= 1.0 - 0.5 * tau / thickness_threshold
        det["rotation_number"] = rotation_number(Q)
        det["reason"] = (f"aperiodic, points on a curve (local thickness {tau:.2f}, correlation dimension {D2:.2f}), "
                         f"no divergence (Lyapunov {lam:.3g}/section <= {lyap_threshold}); rotation number "
                         f"{det['rotation_number']:.3f}")
    conf *= min(1.0, math.sqrt(n / 100.0))  # fewer than 100 points: less confidence
    if np.isfinite(K):
        if (K > k01_threshold) == (label == "chaos"):
            conf = min(1.0, conf + 0.1)
            det["reason"] += f"; 0-1 test agrees (K = {K:.2f})"
        else:
            conf *= 0.6
            det["reason"] += f"; 0-1 test disagrees (K = {K:.2f})"
    return label, float(round(min(max(conf, 0.0), 1.0), 3)), det


# ----------------------------------------------------------------------------- sub-labels and instability indicator

#: Closed vocabulary of ``classification_detail`` (the sub-label of a class; '' when there is none).
#: "1 period" of seed 004 (Figs. 5a, 6a, 8b, 9b, 11a: "single circle whirl" + one Poincare point) is
#: split into what the section alone cannot tell apart:
#:   "still cage"            the cage centre does not move (fixed point, concentric or offset): one
#:                           section point because nothing moves, not because a whirl closes;
#:   "synchronous whirl"     a single-circle whirl closing once per cage revolution (whirl / cage speed = +-1):
#:                           the paper's "1 period" (Fig. 5a);
#:   "harmonic whirl"        a whirl at an integer multiple n >= 2 of the cage speed (also one section point);
#:   "synchronous orbit"     any other closed orbit repeating once per cage revolution (not a circle).
DETAILS = ("", "still cage", "synchronous whirl", "harmonic whirl", "synchronous orbit")

#: Thresholds of :func:`classification_detail` (decisions in docs/analysis.md, "Sub-labels of 1 period").
DETAIL_DEFAULTS = dict(
    still_fraction=0.01,  # orbit RMS radius about its own centre < 1 % of the guide clearance: still
    circle_spread=0.15,  # sd / mean of the radius about the orbit centre <= 0.15: a circle
    ratio_tol=0.1,  # |whirl frequency / cage rotation frequency| within 0.1 of an integer
)


def _orbit_about_centre(y, z):
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(y) & np.isfinite(z)
    y, z = y[ok], z[ok]
    yc, zc = float(np.mean(y)), float(np.mean(z))
    return y - yc, z - zc


def classification_detail(label: str, t, y, z, cage_speed, clearance: float, *,
                          still_fraction: float = DETAIL_DEFAULTS["still_fraction"],
                          circle_spread: float = DETAIL_DEFAULTS["circle_spread"],
                          ratio_tol: float = DETAIL_DEFAULTS["ratio_tol"]) -> tuple[str, dict]:
    """Sub-label of a classification from the continuous cage-centre orbit (after the transient).

    Only ``"1 period"`` has sub-labels (:data:`DETAILS`); other labels return ``""``.  Seed 004
    pairs "1 period" with "the single circle whirl" of the cage centre and one Poincare point
    (Zhang et al. 2016, Sec. 4, Fig. 5a); the cage-revolution section gives one point as well for a
    cage centre that does not move at all, so the orbit itself decides:

    1. RMS distance of the orbit from its own centre ``rho`` < ``still_fraction`` x guide clearance
       -> ``"still cage"`` (the mean offset of the centre is reported, not judged);
    2. else the whirl frequency f_w (dominant frequency of (y - mean) + i (z - mean)) over the cage
       rotation frequency f_c = mean(cage_speed) / 2 pi; ``n = round(|f_w / f_c|)``;
       the radius about the orbit centre has sd/mean <= ``circle_spread`` (a circle) and
       ``| |f_w / f_c| - n | <= ratio_tol``: n = 1 -> ``"synchronous whirl"``, n >= 2 ->
       ``"harmonic whirl"``;
    3. otherwise ``"synchronous orbit"`` (a closed non-circular orbit, or a circle whose frequency
       ratio is not an integer -- the section still repeats, e.g. a whirl locked to the section
       through the ball-pass excitation).

    Parameters
    ----------
    label : str
        The class from :func:`classify`.
    t : (n,) array_like
        Time [s] of the orbit samples.
    y, z : (n,) array_like
        Cage mass-centre displacements D_Y, D_Z [m].
    cage_speed : (n,) array_like or float
        Cage rotation speed about X [rad/s].
    clearance : float
        Guide clearance (radial) [m]; the scale of "still".

    Returns
    -------
    detail : str
        One of :data:`DETAILS`.
    info : dict
        ``orbit_rms_radius`` [m] (about the orbit centre), ``orbit_offset`` [m] (of the orbit
        centre from the bearing axis), ``radius_spread`` [1], ``whirl_cage_ratio`` [1] (signed),
        ``harmonic`` (n) and ``reason``.
    """
    info: dict = {"orbit_rms_radius": None, "orbit_offset": None, "radius_spread": None,
                  "whirl_cage_ratio": None, "harmonic": None, "reason": ""}
    if label != "1 period":
        return "", info
    from hsbearing.analysis.spectrum import whirl_frequency

    t = np.asarray(t, float)
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(t) & np.isfinite(y) & np.isfinite(z)
    t, y, z = t[ok], y[ok], z[ok]
    if len(t) < 16:
        info["reason"] = "fewer than 16 orbit samples"
        return "", info
    info["orbit_offset"] = float(math.hypot(np.mean(y), np.mean(z)))
    dy, dz = _orbit_about_centre(y, z)
    r = np.hypot(dy, dz)
    rho = float(np.sqrt(np.mean(r * r)))
    info["orbit_rms_radius"] = rho
    c = float(clearance) if clearance and math.isfinite(clearance) and clearance > 0 else float("nan")
    if math.isfinite(c) and rho < still_fraction * c:
        info["reason"] = (f"cage centre at rest: orbit RMS radius {rho:.3g} m < {still_fraction:g} x guide "
                          f"clearance {c:.3g} m (offset {info['orbit_offset']:.3g} m)")
        return "still cage", info
    rbar = float(np.mean(r))
    spread = float(np.std(r) / rbar) if rbar > 0 else float("inf")
    info["radius_spread"] = spread
    w = np.asarray(cage_speed, float)
    w = float(np.nanmean(w[ok] if w.ndim and w.size == ok.size else w))
    fw = whirl_frequency(t, y, z)
    ratio = 2 * math.pi * fw / w if (w != 0 and math.isfinite(fw)) else float("nan")
    info["whirl_cage_ratio"] = ratio
    if math.isfinite(ratio):
        n = int(round(abs(ratio)))
        info["harmonic"] = n
        if spread <= circle_spread and n >= 1 and abs(abs(ratio) - n) <= ratio_tol:
            kind = "synchronous whirl" if n == 1 else "harmonic whirl"
            info["reason"] = (f"circular whirl (radius sd/mean {spread:.2f} <= {circle_spread}) at {ratio:+.3f} x "
                              f"the cage speed, radius {rbar:.3g} m")
            return kind, info
    info["reason"] = (f"closed orbit repeating once per cage revolution, not a single circle at an integer multiple "
                      f"of the cage speed (radius sd/mean {spread:.2f}, whirl/cage {ratio:+.3f})")
    return "synchronous orbit", info


def cage_instability_index(y, z, clearance: float | None = None, floor_fraction: float = 0.05) -> float:
    """Normalised whirl-radius dispersion sigma_r / r_mean of the cage mass centre [1].

    r = sqrt(D_Y^2 + D_Z^2) is the whirl radius about the bearing axis, sigma_r its standard
    deviation and r_mean its mean over the samples given (after the transient).  Ghaisas, Wassgren &
    Sadeghi (2004, "Cage instabilities in cylindrical roller bearings", ASME J. Tribol. 126,
    681-689) judge cage stability by the dispersion of the cage whirl about its mean orbit: a
    steady circular whirl about the bearing axis has a constant radius (index 0), an irregular
    whirl one that varies (index of order 0.3-1).

    Departure (documented in docs/sweeps.md, "Cage-stability maps"): with ``clearance`` given,
    r_mean is floored at ``floor_fraction`` x clearance, so a cage almost at rest on the bearing axis
    (r_mean -> 0, ratio 0/0 of noise) reads as stable instead of a random number; the floor does not
    change the index of any whirl using more than 5 % of the clearance.

    Parameters
    ----------
    y, z : array_like
        Cage mass-centre displacements D_Y, D_Z [m].
    clearance : float, optional
        Guide clearance [m] (for the floor).
    floor_fraction : float
        Floor of r_mean as a fraction of the clearance [1].

    Returns
    -------
    float
        sigma_r / max(r_mean, floor) [1]; NaN with fewer than 2 finite samples.
    """
    y = np.asarray(y, float)
    z = np.asarray(z, float)
    ok = np.isfinite(y) & np.isfinite(z)
    if ok.sum() < 2:
        return float("nan")
    r = np.hypot(y[ok], z[ok])
    den = float(np.mean(r))
    if clearance is not None and math.isfinite(clearance) and clearance > 0:
        den = max(den, floor_fraction * float(clearance))
    if den <= 0:
        return 0.0
    return float(np.std(r) / den)  # [1] dispersion of the whirl radius about its mean
