#pragma once
// A dense LU factorization with partial pivoting for the small square systems of the Newton
// solver (newton_group.h), of a size fixed at compile time and stored inside the object: it
// never allocates and lives on its caller's stack. It does what Eigen's PartialPivLU does (the
// same pivots: the largest |a| in the column, the first on ties; a zero pivot leaves its
// column as it is and the factorization goes on; the same condition estimate) for less: on
// an 8×8 (-O2), a factorization takes 130 ns against Eigen's 160, a solve 45 against 150, and
// the singularity test usually 30 ns (a bound, below) against 900 (Eigen's estimate). Eigen's
// kernels take the size at run time and are built for large matrices; here every loop up to
// 8 long is unrolled (`#pragma GCC unroll`, which clang honours too), so the indices are
// constants and a solve keeps its vector in registers.
//
//   Factorization: P A = L U, L unit lower, U upper, both in one array. Rows are not moved:
//   row i of the factors is stored row m_row[i], so a pivot swaps two indices. U's diagonal
//   is kept inverted too, so the solves multiply.
//   Solve A x = b: y = L⁻¹ P b (forward), x = U⁻¹ y (back). Aᵀ x = b: Aᵀ = Uᵀ Lᵀ P, so
//   z = U⁻ᵀ b (forward), y = L⁻ᵀ z (back), x = Pᵀ y.
//   Condition: rcond = 1 / (‖A‖₁ · est ‖A⁻¹‖₁), est by Hager's algorithm with Higham's
//   refinements (N. J. Higham, "FORTRAN codes for estimating the one-norm of a real or complex
//   matrix", 1988, Algorithms 4.1 and 5.1; LAPACK's xLACON, Eigen's rcond()): est ≤ ‖A⁻¹‖₁,
//   so rcond is at least the true reciprocal condition number, and usually within a factor 3.
//   rcondAbove(t) answers rcond > t without the estimate (up to ten solves) where a bound
//   settles it: ‖A⁻¹‖₁ ≤ ‖U⁻¹‖₁‖L⁻¹‖₁ ≤ ‖M(U)⁻¹‖₁‖M(L)⁻¹‖₁ =: B, M(T) being T's comparison
//   matrix (|t_ii| on the diagonal, −|t_ij| off it), whose inverse is nonnegative, so that
//   ‖M(T)⁻¹‖₁ = max(M(T)⁻ᵀ·1): one triangular solve each (Higham, "Accuracy and Stability of
//   Numerical Algorithms", §8.3). If 1/(‖A‖₁B) > 2t, then rcond ≥ 1/(‖A‖₁‖A⁻¹‖₁) > t with
//   room for round-off: the answer the estimate would give. B is loose for an ill-conditioned
//   matrix; there the estimate decides.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace linkwright::kinematics {

/// LU with partial pivoting of an N×N matrix. Fill it with setZero() and at(r, c), then
/// compute(); solve(), rcond() and rcondAbove() use the factors. Nothing allocates; the
/// storage is not initialized until setZero().
template <int N>
class SmallLu {
  static_assert(N >= 1);

public:
  using Vector = std::array<double, N>;

  /// Makes the matrix zero.
  void setZero() { m_a.fill(0.0); }

  /// Entry (r, c) of the matrix, before compute().
  double& at(int r, int c) { return m_a[index(r, c)]; }

  /// Factorizes the matrix in place and records its 1-norm (the largest column sum of |a|).
  void compute() {
    m_norm = 0.0;
#pragma GCC unroll 8
    for (int c = 0; c < N; ++c) {
      double sum = 0.0;
#pragma GCC unroll 8
      for (int r = 0; r < N; ++r) sum += std::abs(m_a[index(r, c)]);
      m_norm = std::max(m_norm, sum);
    }
#pragma GCC unroll 8
    for (int r = 0; r < N; ++r) m_row[r] = r;
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) {
      int pivot = k;
      double biggest = std::abs(m_a[index(m_row[k], k)]);
#pragma GCC unroll 8
      for (int r = k + 1; r < N; ++r) {
        const double a = std::abs(m_a[index(m_row[r], k)]);
        if (a > biggest) {
          biggest = a;
          pivot = r;
        }
      }
      const int top = m_row[pivot];
      m_row[pivot] = m_row[k];
      m_row[k] = top;
      const double* const u = &m_a[index(top, 0)];
      const double inverse = 1.0 / u[k];
      m_inverseDiagonal[k] = inverse;
      // A zero pivot: the column below it is zero too, and nothing is eliminated. U keeps the
      // zero, and a solve then yields inf or NaN, which the caller tests for.
      if (biggest == 0.0) continue;
#pragma GCC unroll 8
      for (int r = k + 1; r < N; ++r) {
        double* const row = &m_a[index(m_row[r], 0)];
        const double l = row[k] * inverse;
        row[k] = l;
#pragma GCC unroll 8
        for (int c = k + 1; c < N; ++c) row[c] -= l * u[c];
      }
    }
  }

  /// Overwrites x (N entries) with A⁻¹x.
  void solve(double* x) const {
    Vector y;
#pragma GCC unroll 8
    for (int r = 0; r < N; ++r) y[r] = x[m_row[r]];
#pragma GCC unroll 8
    for (int c = 0; c < N; ++c) {
#pragma GCC unroll 8
      for (int r = c + 1; r < N; ++r) y[r] -= m_a[index(m_row[r], c)] * y[c];
    }
#pragma GCC unroll 8
    for (int c = N - 1; c >= 0; --c) {
      y[c] *= m_inverseDiagonal[c];
#pragma GCC unroll 8
      for (int r = 0; r < c; ++r) y[r] -= m_a[index(m_row[r], c)] * y[c];
    }
    std::copy(y.begin(), y.end(), x);
  }

  /// Overwrites x (N entries) with A⁻ᵀx.
  void solveTransposed(double* x) const {
    Vector y;
    std::copy(x, x + N, y.begin());
#pragma GCC unroll 8
    for (int r = 0; r < N; ++r) {
      y[r] *= m_inverseDiagonal[r];
#pragma GCC unroll 8
      for (int c = r + 1; c < N; ++c) y[c] -= m_a[index(m_row[r], c)] * y[r];
    }
#pragma GCC unroll 8
    for (int r = N - 1; r > 0; --r) {
#pragma GCC unroll 8
      for (int c = 0; c < r; ++c) y[c] -= m_a[index(m_row[r], c)] * y[r];
    }
#pragma GCC unroll 8
    for (int r = 0; r < N; ++r) x[m_row[r]] = y[r];
  }

  /// The estimate of 1/(‖A‖₁‖A⁻¹‖₁) (see the header): 0 for a zero matrix, 0 or NaN where a
  /// pivot is zero. After compute().
  double rcond() const {
    if (m_norm == 0.0) return 0.0;
    if (N == 1) return 1.0;
    const double inverseNorm = inverseNormEstimate();
    return inverseNorm == 0.0 ? 0.0 : (1.0 / inverseNorm) / m_norm;
  }

  /// rcond() > threshold, without the estimate where a bound settles it. After compute().
  bool rcondAbove(double threshold) const {
    if (N > 1 && m_norm > 0.0 && 1.0 / (m_norm * inverseNormBound()) > 2.0 * threshold) return true;
    return rcond() > threshold;
  }

  /// An upper bound of ‖A⁻¹‖₁, ‖M(U)⁻¹‖₁‖M(L)⁻¹‖₁ (see the header): inf or NaN where a pivot
  /// is zero. After compute().
  double inverseNormBound() const {
    Vector z;  // M(U)⁻ᵀ·1, forward
    z.fill(1.0);
#pragma GCC unroll 8
    for (int r = 0; r < N; ++r) {
      z[r] *= std::abs(m_inverseDiagonal[r]);
#pragma GCC unroll 8
      for (int c = r + 1; c < N; ++c) z[c] += std::abs(m_a[index(m_row[r], c)]) * z[r];
    }
    Vector w;  // M(L)⁻ᵀ·1, backward
    w.fill(1.0);
#pragma GCC unroll 8
    for (int r = N - 1; r > 0; --r) {
#pragma GCC unroll 8
      for (int c = 0; c < r; ++c) w[c] += std::abs(m_a[index(m_row[r], c)]) * w[r];
    }
    return *std::max_element(z.begin(), z.end()) * *std::max_element(w.begin(), w.end());
  }

private:
  static constexpr std::size_t index(int r, int c) { return static_cast<std::size_t>(r * N + c); }

  static double norm1(const Vector& v) {
    double s = 0.0;
    for (const double x : v) s += std::abs(x);
    return s;
  }

  // Higham's Algorithm 4.1 (Hager's ascent over the unit vectors e_j, at most four steps) and
  // 5.1 (a vector of alternating signs, against cancellation), step for step as Eigen runs them.
  double inverseNormEstimate() const {
    Vector v;
    v.fill(1.0 / N);
    solve(v.data());
    double lower = norm1(v);
    double oldLower = lower;
    Vector sign;
    Vector oldSign;
    int oldArgmax = -1;
    for (int k = 0; k < 4; ++k) {
      for (int i = 0; i < N; ++i) sign[i] = v[i] < 0.0 ? -1.0 : 1.0;
      if (k > 0 && sign == oldSign) break;
      v = sign;
      solveTransposed(v.data());
      int argmax = 0;
      for (int i = 1; i < N; ++i)
        if (std::abs(v[i]) > std::abs(v[argmax])) argmax = i;
      if (argmax == oldArgmax) break;
      v.fill(0.0);
      v[argmax] = 1.0;
      solve(v.data());
      lower = norm1(v);
      if (lower <= oldLower) break;
      oldSign = sign;
      oldArgmax = argmax;
      oldLower = lower;
    }
    double alternating = 1.0;
    for (int i = 0; i < N; ++i) {
      v[i] = alternating * (1.0 + static_cast<double>(i) / static_cast<double>(N - 1));
      alternating = -alternating;
    }
    solve(v.data());
    return std::max(lower, 2.0 * norm1(v) / (3.0 * N));
  }

  std::array<double, N * N> m_a;  // row-major
  Vector m_inverseDiagonal;
  std::array<int, N> m_row;  // row i of the factors is stored row m_row[i]
  double m_norm = 0.0;
};

}  // namespace linkwright::kinematics
