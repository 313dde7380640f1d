"""Linear algebra on the arch's block-tridiagonal tangent (numba and scipy): a block couples only with
its two neighbours, so with three degrees of freedom a block K is banded, five diagonals either side,
and is kept in LAPACK's general band storage (ab[BAND + i - j, j] = K[i, j]; a principal block of K
is a slice of its columns). Solves are LAPACK's banded LU with partial pivoting (dgbtf2, dgbtrs)
compiled with numba, called thousands of times a run without scipy's checks and copies; the stability
test by a banded Cholesky factorisation (compiled too) and the softest mode by a banded eigensolver
(scipy) where a state's tables or a saddle's kick need it, on one BLAS thread: its vector's last bits
depend on the thread count, and a stiff arch's path on them."""

from __future__ import annotations

import numpy as np
import scipy.linalg
from numba import njit
from threadpoolctl import threadpool_limits

BAND = 5  # diagonals either side of the main one: 3 degrees of freedom a block, neighbours only


def from_dense(a: np.ndarray) -> np.ndarray:
    """A dense square matrix's band (diagonals beyond BAND are dropped) in general band storage."""
    n = len(a)
    ab = np.zeros((2 * BAND + 1, n))
    for k in range(-min(BAND, n - 1), min(BAND, n - 1) + 1):
        ab[BAND - k, max(0, k) : n + min(0, k)] = np.diagonal(a, k)
    return ab


def to_dense(ab: np.ndarray) -> np.ndarray:
    """The square matrix of a general band storage."""
    n = ab.shape[1]
    a = np.zeros((n, n))
    for k in range(-min(BAND, n - 1), min(BAND, n - 1) + 1):
        rows = np.arange(max(0, -k), n - max(0, k))
        a[rows, rows + k] = ab[BAND - k, rows + k]
    return a


@njit(cache=True)
def symmetric_upper(ab):
    """The symmetric part of a band matrix in upper band storage (LAPACK's, for Cholesky and eigen)."""
    n = ab.shape[1]
    upper = np.zeros((BAND + 1, n))
    for k in range(min(BAND, n - 1) + 1):
        upper[BAND - k, k:] = 0.5 * (ab[BAND - k, k:] + ab[BAND + k, : n - k])
    return upper


def solve(ab: np.ndarray, b: np.ndarray, shift: float = 0.0) -> np.ndarray:
    """x with (K + shift I) x = b, K in general band storage; LinAlgError if singular."""
    x, singular = band_solve(ab, b, shift)
    if singular:
        raise np.linalg.LinAlgError("singular tangent (an exactly zero pivot)")
    return x


@njit(cache=True)
def band_solve(ab, b, shift):
    """(x, singular) with (K + shift I) x = b, K (n x n) in general band storage with BAND diagonals
    either side: LU with partial pivoting in LAPACK's layout (its dgbtf2 then dgbtrs), the upper factor
    widened by BAND rows for the fill-in of row exchanges."""
    n = ab.shape[1]
    kl, ku = BAND, BAND
    kv = kl + ku
    lu = np.zeros((2 * kl + ku + 1, n))
    lu[kl:, :] = ab
    for j in range(n):
        lu[kv, j] += shift
    x = b.copy()
    pivots = np.zeros(n, np.int64)
    last = 0  # the last column the row exchanges so far reach
    for j in range(n):
        below = min(kl, n - 1 - j)
        best, pivot = abs(lu[kv, j]), 0
        for r in range(1, below + 1):
            if abs(lu[kv + r, j]) > best:
                best, pivot = abs(lu[kv + r, j]), r
        pivots[j] = j + pivot
        if lu[kv + pivot, j] == 0.0:
            return x, True
        last = max(last, min(j + ku + pivot, n - 1))
        if pivot != 0:
            for c in range(j, last + 1):
                a, z = kv + j - c, kv + j + pivot - c
                lu[a, c], lu[z, c] = lu[z, c], lu[a, c]
        if below > 0:
            inverse = 1.0 / lu[kv, j]
            for r in range(1, below + 1):
                lu[kv + r, j] *= inverse
            for c in range(j + 1, last + 1):
                factor = lu[kv + j - c, c]
                if factor != 0.0:
                    for r in range(1, below + 1):
                        lu[kv + j + r - c, c] -= lu[kv + r, j] * factor
    for j in range(n - 1):  # L: the exchanges and multipliers in order
        below = min(kl, n - 1 - j)
        p = pivots[j]
        if p != j:
            x[p], x[j] = x[j], x[p]
        for r in range(1, below + 1):
            x[j + r] -= lu[kv + r, j] * x[j]
    for j in range(n - 1, -1, -1):  # U: upper triangular with kv diagonals above the main one
        x[j] /= lu[kv, j]
        for i in range(max(0, j - kv), j):
            x[i] -= lu[kv + i - j, j] * x[j]
    return x, False


@njit(cache=True)
def cholesky_upper(ab):
    """(U, success): the banded Cholesky factor S = U^T U of the symmetric part S of K (LAPACK's dpbtf2
    on the upper band, compiled), success False at the first pivot that is not positive."""
    n = ab.shape[1]
    upper = symmetric_upper(ab)
    for j in range(n):
        pivot = upper[BAND, j]
        if not pivot > 0.0:
            return upper, False
        pivot = np.sqrt(pivot)
        upper[BAND, j] = pivot
        below = min(BAND, n - 1 - j)
        for c in range(1, below + 1):  # row j of the factor
            upper[BAND - c, j + c] /= pivot
        for q in range(1, below + 1):  # the trailing block less the row's outer product
            row_q = upper[BAND - q, j + q]
            for p in range(1, q + 1):
                upper[BAND - (q - p), j + q] -= upper[BAND - p, j + p] * row_q
    return upper, True


@njit(cache=True)
def positive_definite(ab):
    """Whether the symmetric part of K is positive definite (its Cholesky factor exists)."""
    return cholesky_upper(ab)[1]


INVERSE_ITERATIONS = 60  # inverse iterations before the eigensolver is asked instead (set 2's states: 7-19)
INVERSE_RESIDUAL = 1e-9  # |S x - value x| below this x |value| ends them (the value's error is about the
# residual's square over the gap to the next eigenvalue), ...
ROUNDOFF_RESIDUAL = 100.0 * np.finfo(float).eps  # ... or below this x |S| (1-norm): round-off of S x, which
# a nearly singular state's |value| / |S| of 1e-8 would never pass


def smallest_eigenvalue(ab: np.ndarray) -> float:
    """The smallest eigenvalue of the symmetric part of K (N/m for a stiffness): > 0 when stable. Where K
    is stable, by inverse iteration on its Cholesky factor (solves of 1-2 us); elsewhere, or if that does
    not settle, by LAPACK's banded eigensolver."""
    factor, stable = cholesky_upper(ab)
    if stable:
        floor = ROUNDOFF_RESIDUAL * float(np.abs(ab).sum(axis=0).max())
        value, settled = _inverse_iteration(ab, factor, INVERSE_ITERATIONS, INVERSE_RESIDUAL, floor)
        if settled:
            return float(value)
    return _eigen(ab, vectors=False)[0]


@njit(cache=True)
def _inverse_iteration(ab, factor, iterations, residual, floor):
    """(the smallest eigenvalue of the symmetric part S = U^T U of K, settled): x <- S^-1 x from a fixed
    start and its Rayleigh quotient, until |S x - value x| is below `residual` x |value| or `floor`."""
    n = factor.shape[1]
    x = 1.0 + 0.5 * np.sin(np.arange(1.0, n + 1.0))  # a fixed start no eigenvector is orthogonal to in practice
    x /= np.sqrt(x @ x)
    for _ in range(iterations):
        y = x.copy()
        for j in range(n):  # U^T z = x
            for i in range(max(0, j - BAND), j):
                y[j] -= factor[BAND + i - j, j] * y[i]
            y[j] /= factor[BAND, j]
        for i in range(n - 1, -1, -1):  # U y = z
            for j in range(i + 1, min(n, i + BAND + 1)):
                y[i] -= factor[BAND + i - j, j] * y[j]
            y[i] /= factor[BAND, i]
        x = y / np.sqrt(y @ y)
        sx = np.zeros(n)  # S x = (K x + K^T x) / 2 from the general band
        for j in range(n):
            for i in range(max(0, j - BAND), min(n, j + BAND + 1)):
                sx[i] += 0.5 * ab[BAND + i - j, j] * x[j]
                sx[j] += 0.5 * ab[BAND + i - j, j] * x[i]
        value = x @ sx
        if np.sqrt(((sx - value * x) ** 2).sum()) <= max(residual * abs(value), floor):
            return value, True
    return np.nan, False


def softest_mode(ab: np.ndarray) -> tuple[float, np.ndarray]:
    """The smallest eigenvalue of the symmetric part of K and its eigenvector."""
    value, vector = _eigen(ab, vectors=True)
    assert vector is not None
    return value, vector


def _eigen(ab: np.ndarray, vectors: bool) -> tuple[float, np.ndarray | None]:
    """The smallest eigenvalue of the symmetric part of K (and its eigenvector) by LAPACK's banded
    eigensolver on one BLAS thread, so that the same K gives the same bits in any process."""
    with threadpool_limits(limits=1, user_api="blas"):
        found = scipy.linalg.eig_banded(
            symmetric_upper(ab), eigvals_only=not vectors, select="i", select_range=(0, 0), check_finite=False
        )
    if not vectors:
        return float(found[0]), None
    values, vector = found
    return float(values[0]), vector[:, 0]
