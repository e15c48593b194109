#include <catch2/catch.hpp>

#include "optim/convergence.hpp"
#include "optim/gabor_pipeline.hpp"
#include "optim/sigma_schedule.hpp"

using namespace ppsynth;

TEST_CASE("Sigma schedule: d/c1 down to d/c2, evenly spaced", "[optim]") {
  auto s = sigma_schedule(0.1, 1.0, 2.6, 4);
  REQUIRE(s.size() == 4);
  CHECK(s[0] == Approx(0.1));
  CHECK(s[3] == Approx(0.1 / 2.6));
  CHECK(s[1] - s[0] == Approx(s[2] - s[1]));
  CHECK_THROWS_AS(sigma_schedule(0.1, 0.0, 2.6), InputError);
}

TEST_CASE("Convergence rule as the published code checks it", "[optim]") {
  ConvergenceRule rule;
  std::vector<double> L;
  // Fast decay then flat: fires at the first check after 100 iterations.
  for (int i = 0; i < 200; ++i) L.push_back(i < 10 ? 1.0 - 0.09 * i : 0.1);
  std::vector<double> prefix(L.begin(), L.begin() + 100);
  CHECK_FALSE(rule.converged(prefix, 99));  // not more than 100 yet
  std::vector<double> p111(L.begin(), L.begin() + 111);
  CHECK(rule.converged(p111, 110));
  std::vector<double> p112(L.begin(), L.begin() + 112);
  CHECK_FALSE(rule.converged(p112, 111));  // only every 10th iteration
  // Steady linear decrease: 100 of 110 iterations' worth of decrease is far above 1%.
  std::vector<double> lin;
  for (int i = 0; i < 111; ++i) lin.push_back(1.0 - 0.001 * i);
  CHECK_FALSE(rule.converged(lin, 110));
}

TEST_CASE("Toroidal wrap as published", "[optim]") {
  auto x = torch::tensor({-0.25, 0.5, 1.25, 2.5, -1.5});
  auto w = wrap_unit(x);
  CHECK(w[0].item<float>() == Approx(0.75));
  CHECK(w[1].item<float>() == Approx(0.5));
  CHECK(w[2].item<float>() == Approx(0.25));
  CHECK(w[3].item<float>() == Approx(0.5));
  CHECK(w[4].item<float>() == Approx(0.5));
  auto p = x.clone().set_requires_grad(true);
  wrap_unit(p).sum().backward();
  CHECK(torch::equal(p.grad(), torch::ones_like(x)));
}
