#include <catch2/catch.hpp>

#include "losses/autocorrelation.hpp"
#include "losses/composite_loss.hpp"
#include "losses/gram_loss.hpp"

using namespace ppsynth;

namespace {
torch::Tensor rnd(std::vector<int64_t> s, uint64_t seed) {
  auto g = at::detail::createCPUGenerator(seed);
  return at::rand(s, g, torch::kFloat64);
}
// Direct cross-correlation sum_ij x(i+a, j+b) k(i, j) over the kept lags, for the published
// gradient's reference.
torch::Tensor cross_direct(const torch::Tensor& x, const torch::Tensor& k, int q) {
  const int64_t H = x.size(1), W = x.size(2);
  std::vector<torch::Tensor> rows;
  for (int a = -(q / 2); a <= (q + 1) / 2 - 1; ++a) {
    std::vector<torch::Tensor> cols;
    for (int b = -(q / 2); b <= (q + 1) / 2 - 1; ++b) {
      int64_t i0 = std::max(0, -a), i1 = std::min<int64_t>(H, H - a), j0 = std::max(0, -b), j1 = std::min<int64_t>(W, W - b);
      auto s = (x.slice(1, i0 + a, i1 + a).slice(2, j0 + b, j1 + b) * k.slice(1, i0, i1).slice(2, j0, j1)).sum({1, 2});
      cols.push_back(s / double((H - std::abs(a)) * (W - std::abs(b))));
    }
    rows.push_back(torch::stack(cols, 1));
  }
  return torch::stack(rows, 1);
}
}  // namespace

TEST_CASE("Deep correlation of a hand-computed 2x2 map", "[losses][correlation]") {
  auto F = torch::tensor({1.0, 2.0, 3.0, 4.0}, torch::kFloat64).view({1, 1, 2, 2});
  auto C = deep_correlation(F, 3, 3)[0];
  CHECK(C[1][1].item<double>() == Approx(7.5));  // (1+4+9+16)/4
  CHECK(C[1][2].item<double>() == Approx(7.0));  // (1*2 + 3*4)/2
  CHECK(C[1][0].item<double>() == Approx(7.0));
  CHECK(C[2][1].item<double>() == Approx(5.5));  // (1*3 + 2*4)/2
  CHECK(C[2][2].item<double>() == Approx(4.0));  // 1*4
  CHECK(C[2][0].item<double>() == Approx(6.0));  // 2*3
}

TEST_CASE("FFT deep correlation equals the direct sum, values and exact gradient", "[losses][correlation]") {
  for (int q : {3, 4, 6, 11}) {
    auto F = rnd({1, 3, 6, 6}, 10 + q);
    auto fa = F.clone().set_requires_grad(true), fb = F.clone().set_requires_grad(true);
    auto probe = rnd({3, q, q}, 20);
    auto a = deep_correlation(fa, q, q);
    auto b = deep_correlation_direct(fb, q, q);
    CHECK(torch::allclose(a, b, 1e-10, 1e-12));
    (a * probe).sum().backward();
    (b * probe).sum().backward();
    CHECK(torch::allclose(fa.grad(), fb.grad(), 1e-9, 1e-12));
  }
}

TEST_CASE("Deep correlation of a rectangle map: FFT equals the direct sum, each lag a mean over its overlap",
          "[losses][correlation]") {
  // A rectangle output's features are rows x columns (optim/gabor/windows/window_plan.hpp): each lag is
  // still a mean over the positions it pairs, so a constant map correlates to its square at
  // every lag, whatever the aspect, and the targets' crop (the exemplar's layer) applies.
  for (const auto& [h, w] : {std::pair{5, 9}, std::pair{9, 4}}) {
    auto F = rnd({1, 2, h, w}, 40 + h);
    auto fa = F.clone().set_requires_grad(true), fb = F.clone().set_requires_grad(true);
    auto probe = rnd({2, 5, 7}, 41);
    auto a = deep_correlation(fa, 5, 7);
    auto b = deep_correlation_direct(fb, 5, 7);
    INFO(h << " x " << w);
    CHECK(torch::allclose(a, b, 1e-10, 1e-12));
    (a * probe).sum().backward();
    (b * probe).sum().backward();
    CHECK(torch::allclose(fa.grad(), fb.grad(), 1e-9, 1e-12));
    CHECK(torch::allclose(deep_correlation(torch::full({1, 1, h, w}, 3.0, torch::kFloat64), 5, 7),
                          torch::full({1, 5, 7}, 9.0, torch::kFloat64), 1e-12, 1e-12));
  }
}

TEST_CASE("Published correlation gradient: same values, last channel as kernel", "[losses][correlation]") {
  const int q = 4;
  auto F = rnd({1, 3, 6, 6}, 30);
  auto probe = rnd({3, q, q}, 31);
  auto fp = F.clone().set_requires_grad(true);
  auto pub = deep_correlation(fp, q, q, CorrelationGradient::Published);
  CHECK(torch::allclose(pub, deep_correlation(F, q, q), 1e-10, 1e-12));
  (pub * probe).sum().backward();
  // Reference: x side differentiable, kernel = last channel detached.
  auto x = F[0].clone().set_requires_grad(true);
  auto klast = F[0][2].detach().unsqueeze(0).expand({3, 6, 6});
  (cross_direct(x, klast, q) * probe).sum().backward();
  CHECK(torch::allclose(fp.grad()[0], x.grad(), 1e-9, 1e-12));
  // And it differs from the exact gradient.
  auto fe = F.clone().set_requires_grad(true);
  (deep_correlation(fe, q, q) * probe).sum().backward();
  CHECK((fe.grad() - fp.grad()).abs().max().item<double>() > 1e-3);
}

TEST_CASE("Every registered loss is zero on identical features and positive otherwise", "[losses]") {
  Features ex = {rnd({1, 4, 8, 8}, 1), rnd({1, 4, 4, 4}, 2), rnd({1, 4, 2, 2}, 3)};
  // Output at u = 2: twice the size per axis.
  Features same = ex;
  Features other = {rnd({1, 4, 16, 16}, 4), rnd({1, 4, 8, 8}, 5), rnd({1, 4, 4, 4}, 6)};
  for (auto& name : LossRegistry::instance().names()) {
    if (name.rfind("test_", 0) == 0) continue;  // losses registered by other test files
    INFO(name);
    auto loss = LossRegistry::instance().create(json{{"type", name}}, "loss");
    LossContext ctx{1, 7};
    loss->set_target(ex, ctx);
    CHECK(loss->forward(same).item<double>() == Approx(0.0).margin(1e-12));
    ctx.upscale = 2;
    loss->set_target(ex, ctx);
    auto o = other;
    for (auto& t : o) t.set_requires_grad(true);
    auto v = loss->forward(o);
    CHECK(v.item<double>() > 1e-6);
    v.backward();
    double gsum = 0;
    for (auto& t : o)
      if (t.grad().defined()) gsum += t.grad().abs().sum().item<double>();
    CHECK(gsum > 0);
  }
}

TEST_CASE("Composite loss from config: weights, defaults, errors naming the key", "[losses]") {
  json spec = json::array({json{{"type", "gram"}, {"weight", 0.5}}, json{{"type", "correlation"}}});
  CompositeLoss loss(spec);
  REQUIRE(loss.terms().size() == 2);
  CHECK(loss.terms()[0].weight == 0.5);
  CHECK(loss.terms()[1].weight == 1.0);
  CHECK(loss.resolved()[1]["gradient"] == "exact");
  Features ex = {rnd({1, 4, 8, 8}, 1), rnd({1, 4, 4, 4}, 2), rnd({1, 4, 2, 2}, 3)};
  Features out = {rnd({1, 4, 8, 8}, 8), rnd({1, 4, 4, 4}, 9), rnd({1, 4, 2, 2}, 10)};
  loss.set_target(ex, LossContext{1, 1});
  auto total = loss.forward(out).item<double>();
  CHECK(total == Approx(0.5 * loss.terms()[0].last_value() + loss.terms()[1].last_value()));
  CHECK_THROWS_WITH(CompositeLoss(json::array({json{{"type", "gram"}, {"wieght", 1}}})), Catch::Contains("losses[0].wieght"));
  CHECK_THROWS_WITH(CompositeLoss(json::array({json{{"type", "correlation"}, {"gradient", "fast"}}})), Catch::Contains("losses[0].gradient"));
  CHECK_THROWS_WITH(CompositeLoss(json::array({json{{"type", "nope"}}})), Catch::Contains("losses[0].type"));
}

TEST_CASE("Gram matrix: values and gradient equal the direct formula, NCHW and channels-last", "[losses][gram]") {
  torch::manual_seed(3);
  auto F0 = torch::randn({1, 5, 6, 7}, torch::kFloat64);
  auto W = torch::randn({5, 5}, torch::kFloat64);  // a non-symmetric upstream gradient
  auto direct = F0.detach().clone().set_requires_grad(true);
  auto f = direct.reshape({5, -1});
  auto G_direct = torch::mm(f, f.t()) / static_cast<double>(F0.numel());
  (G_direct * W).sum().backward();
  for (auto fmt : {at::MemoryFormat::Contiguous, at::MemoryFormat::ChannelsLast}) {
    auto F = F0.detach().contiguous(fmt).set_requires_grad(true);
    auto G = gram_matrix(F);
    CHECK(torch::allclose(G, G_direct, 1e-12, 1e-14));
    (G * W).sum().backward();
    CHECK(torch::allclose(F.grad(), direct.grad(), 1e-12, 1e-14));
  }
}
