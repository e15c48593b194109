# spatstat's K, L, g (and cross-type K, L, g; mark correlation) of a ppsynth plain point file,
# with spatstat's defaults (r grid, Epanechnikov kernel and Stoyan's bandwidth for g), both
# edge corrections: the reference that tests/core/test_spatstat_estimators.cpp holds
# ppsynth's estimators (core/metrics/second_order.hpp, mark_correlation.hpp) to.
#
#   Rscript scripts/spatstat_summaries.R FILE
#
# FILE: plain text as core/formats/plain_text_format.hpp writes it ("# domain", "# x y
# [class] [ATTR]"); a "class" column makes the pattern multitype, a numeric attribute named
# "mark" (as scripts/spatstat_export.R writes) marked. Prints one line per curve,
#   NAME [I J] CORRECTION v_1 ... v_n
# NAME: r, K, L, g (univariate); rcross, Kcross, Lcross, gcross (types I to J, every ordered
# pair); rmark, markcorr; CORRECTION "iso", "trans" or "-" for r. Values %.17g, NaN as NaN.
suppressPackageStartupMessages(library(spatstat.explore))
source(file.path(dirname(normalizePath(sub("^--file=", "", grep("^--file=", commandArgs(FALSE), value = TRUE)[1]))), "spatstat_io.R"))

args <- commandArgs(trailingOnly = TRUE)
if (length(args) != 1) {
  cat("usage: Rscript scripts/spatstat_summaries.R FILE\n", file = stderr())
  quit(status = 2)
}
X <- read_plain(args[1])
cols <- names(attr(X, "table"))
tab <- attr(X, "table")
X <- unmark(X)

emit <- function(name, corr, v) cat(name, corr, sprintf("%.17g", v), "\n")

K <- Kest(X, correction = c("isotropic", "translate"))
g <- pcf(X, correction = c("isotropic", "translate"))
emit("r", "-", K$r)
emit("K", "iso", K$iso)
emit("K", "trans", K$trans)
emit("L", "iso", sqrt(K$iso / pi))
emit("L", "trans", sqrt(K$trans / pi))
emit("rg", "-", g$r)
emit("g", "iso", g$iso)
emit("g", "trans", g$trans)

if ("class" %in% cols) {
  Y <- X %mark% factor(tab$class)
  for (i in levels(marks(Y))) for (j in levels(marks(Y))) {
    if (i == j) next
    Kc <- Kcross(Y, i, j, correction = c("isotropic", "translate"))
    gc <- pcfcross(Y, i, j, correction = c("isotropic", "translate"))
    emit(paste("rcross", i, j), "-", Kc$r)
    emit(paste("Kcross", i, j), "iso", Kc$iso)
    emit(paste("Kcross", i, j), "trans", Kc$trans)
    emit(paste("rgcross", i, j), "-", gc$r)
    emit(paste("gcross", i, j), "iso", gc$iso)
    emit(paste("gcross", i, j), "trans", gc$trans)
  }
}
if ("mark" %in% cols) {
  Z <- X %mark% tab$mark
  mc <- markcorr(Z, correction = c("isotropic", "translate"))
  emit("rmark", "-", mc$r)
  emit("markcorr", "iso", mc$iso)
  emit("markcorr", "trans", mc$trans)
}
