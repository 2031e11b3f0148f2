#include "algorithms/stress/rigid_body_spring/supernodal_cholesky.h"

#include "algorithms/stress/rigid_body_spring/inline_parallel_regions.h"
#include "algorithms/core/node_ordering.h"

#include <cholmod.h>
#include <omp.h>

#include <cassert>
#include <limits>
#include <optional>
#include <vector>

namespace shatter {

/// The CHOLMOD workspace and factor. CHOLMOD keeps pointers into `common`, so it never moves: the
/// State lives on the heap and only the unique_ptr moves.
struct SupernodalCholesky::State {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;

  State() {
    cholmod_start(&common);
    common.print = 0;                       // no messages on stderr: failures are return values
    common.supernodal = CHOLMOD_SUPERNODAL; // always supernodal (the point of this class)
    common.nmethods = 1;                    // AMD only: METIS orders the walls no better and 3x slower
    common.method[0].ordering = CHOLMOD_AMD;
    common.postorder = 1;
    common.quick_return_if_not_posdef = 1;
  }
  ~State() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  State(const State&) = delete;
  State& operator=(const State&) = delete;
};

namespace {

/// A read-only CHOLMOD view of Eigen's lower triangle (no copy; CHOLMOD does not write it).
cholmod_sparse view_lower(const Eigen::SparseMatrix<double>& lower) {
  assert(lower.isCompressed() && lower.rows() == lower.cols());
  cholmod_sparse a{};
  a.nrow = static_cast<std::size_t>(lower.rows());
  a.ncol = static_cast<std::size_t>(lower.cols());
  a.nzmax = static_cast<std::size_t>(lower.nonZeros());
  a.p = const_cast<int*>(lower.outerIndexPtr());
  a.i = const_cast<int*>(lower.innerIndexPtr());
  a.x = const_cast<double*>(lower.valuePtr());
  a.stype = -1;  // lower triangle stored
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

/// Runs CHOLMOD single-threaded while alive. Debian's CHOLMOD opens OpenMP teams of 4 threads for
/// large supernodes; on 2 shared cores the wake-ups cost more than they gain (evaluating the 23 x 22
/// wall: 6.0 ms with them, 4.2 ms without; the 71 x 71 wall: 156 ms against 82 ms). The bound is a
/// process-wide OpenMP setting, restored on exit; nothing else in shatterbench uses OpenMP. Even a team
/// of one costs a team set-up and a futex wake-up per region, and CHOLMOD opens regions per supernode
/// (~2,000 per factorisation of the 23 x 22 wall's in-plane half), so the guard also asks for the
/// regions of this thread to run as plain calls (inline_parallel_regions.h; honoured when built with
/// SHATTER_INLINE_PARALLEL_REGIONS, the default).
class SingleThreaded {
 public:
  SingleThreaded() : saved_(omp_get_max_active_levels()), saved_inline_(run_parallel_regions_inline) {
    omp_set_max_active_levels(0);
    run_parallel_regions_inline = true;
  }
  ~SingleThreaded() {
    run_parallel_regions_inline = saved_inline_;
    omp_set_max_active_levels(saved_);
  }
  SingleThreaded(const SingleThreaded&) = delete;
  SingleThreaded& operator=(const SingleThreaded&) = delete;

 private:
  int saved_;
  bool saved_inline_;
};

}  // namespace

SupernodalCholesky::SupernodalCholesky() : state_(std::make_unique<State>()) {}
SupernodalCholesky::~SupernodalCholesky() = default;
SupernodalCholesky::SupernodalCholesky(SupernodalCholesky&&) noexcept = default;
SupernodalCholesky& SupernodalCholesky::operator=(SupernodalCholesky&&) noexcept = default;

bool SupernodalCholesky::analyze(const Eigen::SparseMatrix<double>& lower, std::span<const int> groups,
                                 std::span<const int> order) {
  State& s = *state_;
  if (s.factor) cholmod_free_factor(&s.factor, &s.common);
  cholmod_sparse a = view_lower(lower);
  const SingleThreaded single;
  if (groups.empty()) {
    s.common.method[0].ordering = CHOLMOD_AMD;
    s.factor = cholmod_analyze(&a, &s.common);
    return s.factor != nullptr && s.common.status == CHOLMOD_OK;
  }
  std::optional<std::vector<int>> amd = order.empty() ? node_amd_order(lower, groups) : std::nullopt;
  if (order.empty() && !amd) return false;
  const std::span<const int> node_order = order.empty() ? std::span<const int>(*amd) : order;
  // Each node's columns in their order, the nodes in the elimination order.
  const int n = static_cast<int>(lower.cols());
  std::vector<int> first(node_order.size() + 1, n), perm;
  for (int c = n - 1; c >= 0; --c) first[static_cast<std::size_t>(groups[static_cast<std::size_t>(c)])] = c;
  perm.reserve(static_cast<std::size_t>(n));
  for (const int g : node_order)
    for (int c = first[static_cast<std::size_t>(g)]; c < n && groups[static_cast<std::size_t>(c)] == g; ++c) perm.push_back(c);
  s.common.method[0].ordering = CHOLMOD_GIVEN;
  s.factor = cholmod_analyze_p(&a, perm.data(), nullptr, 0, &s.common);
  return s.factor != nullptr && s.common.status == CHOLMOD_OK;
}

double SupernodalCholesky::factor_flops() const { return state_->common.fl; }

std::size_t SupernodalCholesky::factor_bytes() const {
  const cholmod_factor* l = state_->factor;
  if (!l) return 0;
  return l->xsize * sizeof(double) + l->ssize * sizeof(int) + 4 * l->n * sizeof(int);
}

bool SupernodalCholesky::factorize(const Eigen::SparseMatrix<double>& lower) {
  State& s = *state_;
  if (!s.factor) return false;
  cholmod_sparse a = view_lower(lower);
  const SingleThreaded single;
  const int ok = cholmod_factorize(&a, s.factor, &s.common);
  return ok != 0 && s.common.status == CHOLMOD_OK && s.factor->minor == s.factor->n;
}

Eigen::VectorXd SupernodalCholesky::solve(const Eigen::VectorXd& b) const {
  State& s = *state_;
  assert(s.factor && static_cast<std::size_t>(b.size()) == s.factor->n);
  cholmod_dense rhs{};
  rhs.nrow = static_cast<std::size_t>(b.size());
  rhs.ncol = 1;
  rhs.nzmax = rhs.nrow;
  rhs.d = rhs.nrow;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  const SingleThreaded single;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, s.factor, &rhs, &s.common);
  Eigen::VectorXd out;
  if (x) {
    out = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), b.size());
    cholmod_free_dense(&x, &s.common);
  } else {
    out = Eigen::VectorXd::Constant(b.size(), std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

}  // namespace shatter
