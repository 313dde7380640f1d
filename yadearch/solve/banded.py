"""Linear algebra on the arch's block-tridiagonal tangent (pure scipy): a block couples only with its
two neighbours, so with three degrees of freedom a block K is banded, five diagonals either side, and
is kept in LAPACK's general band storage (ab[BAND + i - j, j] = K[i, j]; a principal block of K is a
slice of its columns). Banded solves, the stability test by a banded Cholesky factorisation and the
softest mode by a banded eigensolver cost a few per cent of their dense counterparts."""

from __future__ import annotations

import numpy as np
import scipy.linalg

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


def symmetric_upper(ab: np.ndarray) -> np.ndarray:
    """The symmetric part of a band matrix in upper band storage (LAPACK's, for Cholesky and eigen)."""
    n = ab.shape[1]
    upper = np.zeros((BAND + 1, n))
    for k in range(min(BAND, n - 1) + 1):
        upper[BAND - k, k:] = 0.5 * (ab[BAND - k, k:] + ab[BAND + k, : n - k])
    return upper


def solve(ab: np.ndarray, b: np.ndarray, shift: float = 0.0) -> np.ndarray:
    """x with (K + shift I) x = b, K in general band storage; LinAlgError if singular."""
    shifted = ab.copy()
    shifted[BAND] += shift
    return scipy.linalg.solve_banded((BAND, BAND), shifted, b, check_finite=False)


def positive_definite(ab: np.ndarray) -> bool:
    """Whether the symmetric part of K is positive definite (its Cholesky factor exists)."""
    try:
        scipy.linalg.cholesky_banded(symmetric_upper(ab), check_finite=False)
    except np.linalg.LinAlgError:
        return False
    return True


def smallest_eigenvalue(ab: np.ndarray) -> float:
    """The smallest eigenvalue of the symmetric part of K (N/m for a stiffness): > 0 when stable."""
    values = scipy.linalg.eig_banded(
        symmetric_upper(ab), eigvals_only=True, select="i", select_range=(0, 0), check_finite=False
    )
    return float(values[0])


def softest_mode(ab: np.ndarray) -> np.ndarray:
    """The eigenvector of the smallest eigenvalue of the symmetric part of K."""
    _, vectors = scipy.linalg.eig_banded(symmetric_upper(ab), select="i", select_range=(0, 0), check_finite=False)
    return vectors[:, 0]
