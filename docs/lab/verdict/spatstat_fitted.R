# What a statistician would do instead of ppsynth: fit a point process model to an exemplar with
# spatstat (ppm for Gibbs and Poisson models, kppm for cluster models) and simulate it on the
# output's window. The realizations are the "fitted model" column of docs/lab/verdict/README.md's
# real-data table: eval's verdict should pass them at its nominal rate when the model is
# right.
#
#   Rscript docs/lab/verdict/spatstat_fitted.R EXEMPLAR OUT_STEM DRAWS [U=2 | UxxUy] [MODEL=auto]
#
# EXEMPLAR: a plain point file (scripts/spatstat_export.R writes them; a "class" column makes
# it multitype). DRAWS: a count N (draws 1..N) or a range A:B. Writes OUT_STEM_dNNN.txt on
# [0, Ux W] x [0, Uy H] (exemplar units: eval with --zoom 1), seeded by the draw number. MODEL:
#   poisson        ppm(X ~ 1)                        (multitype: ~ marks)
#   strauss        ppm(X ~ 1, StraussHard(r)): Strauss with a hard core (estimated by
#                  spatstat from the closest pair), r by profile likelihood over 20 values
#                  in [0.2, 2] x the mean nearest-neighbor distance
#   thomas         kppm(X ~ 1, "Thomas")              (minimum contrast on K)
#   multistrauss   ppm(X ~ marks, MultiStraussHard(r)), hard cores per type pair estimated,
#                  one r for pairs of a type and another for pairs of two types, by profile
#                  likelihood as for strauss
#   auto           multitype: multistrauss; else Clark-Evans' index R: R < 0.9 thomas,
#                  R > 1.1 strauss, otherwise poisson
# Prints the model it fitted, with its parameters.
suppressPackageStartupMessages({
  library(spatstat.geom)
  library(spatstat.random)
  library(spatstat.explore)
  library(spatstat.model)
})
source(file.path(dirname(normalizePath(sub("^--file=", "", grep("^--file=", commandArgs(FALSE), value = TRUE)[1]))), "..", "..", "..", "scripts", "spatstat_io.R"))  # the shared reader stays in scripts/

args <- commandArgs(trailingOnly = TRUE)
if (length(args) < 3) {
  cat("usage: Rscript docs/lab/verdict/spatstat_fitted.R EXEMPLAR OUT_STEM DRAWS [U] [MODEL]\n", file = stderr())
  quit(status = 2)
}
draws <- if (grepl(":", args[3])) {
  ab <- as.integer(strsplit(args[3], ":")[[1]])
  seq(ab[1], ab[2])
} else seq_len(as.integer(args[3]))
# U: one factor for both sides, or "UxxUy" for an output of another aspect (e.g. 1.601x1)
U <- if (length(args) >= 4) as.numeric(strsplit(args[4], "x")[[1]]) else 2
if (length(U) == 1) U <- c(U, U)
model <- if (length(args) >= 5) args[5] else "auto"

X <- read_plain(args[1])
W <- Window(X)
multitype <- is.multitype(X)
if (!multitype) X <- unmark(X)

if (model == "auto") {
  model <- if (multitype) "multistrauss" else {
    R <- clarkevans(unmark(X), correction = "Donnelly")
    if (R < 0.9) "thomas" else if (R > 1.1) "strauss" else "poisson"
  }
}
nnd <- mean(nndist(unmark(X)))
radii <- seq(0.2, 2, length.out = 20) * nnd
big <- owin(c(0, U[1] * diff(W$xrange)), c(0, U[2] * diff(W$yrange)))

fit <- switch(model,
  poisson = if (multitype) ppm(X ~ marks) else ppm(X ~ 1),
  strauss = {
    # r must exceed the hard core, which spatstat estimates from the closest pair.
    pr <- profilepl(data.frame(r = radii[radii > 1.05 * min(nndist(X))]), function(r) StraussHard(r), X ~ 1, aic = FALSE)
    as.ppm(pr)
  },
  thomas = kppm(X ~ 1, "Thomas"),
  multistrauss = {
    types <- levels(marks(X))
    k <- length(types)
    # Each r must exceed its pairs' hard core (the closest pair of those types).
    same <- max(sapply(split(X), function(Y) min(nndist(Y))))
    D <- crossdist(split(X)[[1]], split(X)[[2]])
    cross <- if (k == 2) min(D) else min(nndist(unmark(X)))
    grid <- expand.grid(a = radii[seq(2, 20, by = 3)], b = radii[seq(1, 20, by = 3)])
    grid <- grid[grid$b <= grid$a & grid$a > 1.05 * same & grid$b > 1.05 * cross, ]
    make <- function(a, b) {
      m <- matrix(b, k, k)
      diag(m) <- a
      MultiStraussHard(iradii = m, hradii = NULL, types = types)
    }
    pr <- profilepl(grid, make, X ~ marks, aic = FALSE)
    as.ppm(pr)
  },
  stop(paste("unknown model", model)))
cat(sprintf("%s: model %s\n", args[1], model))
print(fit)

# Gibbs models are simulated on the window grown by a margin and clipped: on the window alone
# the points at its edge miss the neighbors beyond it, and crowd there (a free boundary),
# where the exemplar is a window cut out of a larger pattern. Cluster models simulate their
# parents beyond the window themselves.
margin <- 0.25 * min(diff(W$xrange), diff(W$yrange))
for (d in draws) {
  set.seed(d)
  Y <- if (inherits(fit, "kppm")) simulate(fit, nsim = 1, window = big, drop = TRUE) else
    simulate(fit, nsim = 1, w = grow.rectangle(big, margin), drop = TRUE, progress = FALSE)
  if (is.list(Y) && !is.ppp(Y)) Y <- Y[[1]]
  Y <- Y[big]
  write_plain(Y, sprintf("%s_d%03d.txt", args[2], d), sprintf("fitted model: %s, simulated by docs/lab/verdict/spatstat_fitted.R", model))
}
