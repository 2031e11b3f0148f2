// K u and f - K u skipping the zero columns of u: bit for bit Eigen's own expressions, on random
// matrices with explicit zeros and on vectors with zero (and negative-zero) entries.

#include "algorithms/core/random.h"
#include "algorithms/stress/rigid_body_spring/sparse_product.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

using namespace shatter;

namespace {

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const auto bytes = sizeof(double) * static_cast<std::size_t>(a.size());
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), bytes) == 0;
}

}  // namespace

TEST_CASE("sparse product: skipping zero columns gives Eigen's K u and f - K u bit for bit", "[stress]") {
  SplitMix64 random(41);
  int skipped_columns = 0;
  for (int trial = 0; trial < 100; ++trial) {
    INFO("trial " << trial);
    const int n = 20 + trial;
    std::vector<Eigen::Triplet<double>> entries;
    for (int e = 0; e < 8 * n; ++e) {
      const auto i = static_cast<int>(random.uniform() * n * 0.9999);
      const auto j = static_cast<int>(random.uniform() * n * 0.9999);
      // Every fifth value an explicit zero, and magnitudes over many decades (so roundings differ by order).
      const double value = e % 5 == 0 ? 0.0 : random.uniform(-1, 1) * std::pow(10.0, random.uniform(-6, 6));
      entries.emplace_back(i, j, value);
    }
    Eigen::SparseMatrix<double> k(n, n);
    k.setFromTriplets(entries.begin(), entries.end());
    k.makeCompressed();
    Eigen::VectorXd f(n), u(n);
    for (int i = 0; i < n; ++i) {
      f[i] = i % 7 == 0 ? 0.0 : random.uniform(-1e3, 1e3);
      u[i] = i % 3 == 0 ? (i % 2 == 0 ? 0.0 : -0.0) : random.uniform(-1, 1);
      skipped_columns += u[i] == 0.0;
    }
    const Eigen::VectorXd eigen_product = k * u;
    const Eigen::VectorXd eigen_residual = f - k * u;
    CHECK(same_bits(sparse_product(k, u), eigen_product));
    CHECK(same_bits(sparse_residual(k, f, u), eigen_residual));
    // The reported residual norm is formed as (f - K u).norm(): Eigen evaluates K u first there.
    CHECK((f - sparse_product(k, u)).norm() == (f - k * u).norm());
  }
  CHECK(skipped_columns > 1000);
}
