# Simulated exemplars and outputs of known processes for calibrating eval's verdict
# (core/metrics/verdict.hpp; docs/lab/verdict/README.md): spatstat.random draws them, ppsynth judges them.
#
#   Rscript docs/lab/verdict/verdict_simulate.R OUT_DIR DRAWS [U=2] [FIRST=1] [PROCESS ...]
#
# For each process and draw d = FIRST..FIRST+DRAWS-1 (seeded by d: the same files for the same
# arguments; another FIRST gives fresh draws),
# OUT_DIR/PROCESS/ gets, as plain point files (core/formats/plain_text_format.hpp):
#   dNNN_exemplar.txt  a realization on the exemplar window (the unit square)
#   dNNN_same.txt      an independent realization on [0, U] x [0, U] (exemplar units, zoom 1):
#                      the null hypothesis, what a perfect synthesis would give
#   dNNN_csr.txt       uniform points, as many (per class) as dNNN_same.txt: no structure
#   dNNN_ssi.txt       a Poisson-disk pattern (simple sequential inhibition, rSSI) of the same
#                      count, inhibition distance 0.7 x the hexagonal packing distance (0.44 of the
#                      plane covered by the disks; random packing jams at 0.55)
#   dNNN_relabel.txt   (multitype only) dNNN_same.txt with its labels permuted: right
#                      points, wrong pairing of types
# PROCESS (default: all): strauss, hardcore, matern, thomas, lgcp, multitype
#   strauss    Strauss, beta 200, gamma 0.2, R 0.06          (about 100 points)
#   hardcore   hard core, beta 200, R 0.05                     (about 100 points)
#   matern     Matern cluster, kappa 10, scale 0.06, mu 9      (about 90 points, as in the issue)
#   thomas     Thomas, kappa 15, scale 0.03, mu 6              (about 90 points)
#   lgcp       log-Gaussian Cox, exponential covariance, variance 1, scale 0.05, mean 100 points
#   multitype  two independent types: Strauss (beta 100, gamma 0.2, R 0.06) and Matern
#              cluster (kappa 10, scale 0.05, mu 6)
suppressPackageStartupMessages({
  library(spatstat.geom)
  library(spatstat.random)
})
source(file.path(dirname(normalizePath(sub("^--file=", "", grep("^--file=", commandArgs(FALSE), value = TRUE)[1]))), "..", "..", "..", "scripts", "spatstat_io.R"))  # the shared reader stays in scripts/

args <- commandArgs(trailingOnly = TRUE)
if (length(args) < 2) {
  cat("usage: Rscript docs/lab/verdict/verdict_simulate.R OUT_DIR DRAWS [U] [FIRST] [PROCESS ...]\n", file = stderr())
  quit(status = 2)
}
out_dir <- args[1]
draws <- as.integer(args[2])
U <- if (length(args) >= 3) as.numeric(args[3]) else 2
all_processes <- c("strauss", "hardcore", "matern", "thomas", "lgcp", "multitype")
first <- if (length(args) >= 4) as.integer(args[4]) else 1L
processes <- if (length(args) >= 5) args[-(1:4)] else all_processes
bad <- setdiff(processes, all_processes)
if (length(bad) || is.na(draws) || draws < 1 || is.na(U) || U < 1 || is.na(first) || first < 1 || first + draws > 1000) {
  cat("verdict_simulate: unknown process", bad, "or bad DRAWS/U; processes:", all_processes, "\n", file = stderr())
  quit(status = 2)
}

simulate <- function(process, W) {
  switch(process,
    strauss = rStrauss(200, 0.2, 0.06, W),
    hardcore = rHardcore(200, 0.05, W),
    matern = rMatClust(10, 0.06, 9, win = W),
    thomas = rThomas(15, 0.03, 6, win = W),
    lgcp = rLGCP("exponential", mu = log(100) - 0.5, var = 1, scale = 0.05, win = W, saveLambda = FALSE),
    multitype = superimpose(`0` = rStrauss(100, 0.2, 0.06, W), `1` = rMatClust(10, 0.05, 6, win = W)))
}

# Uniform or Poisson-disk points with the counts of X per type, on X's window.
same_counts <- function(X, generate) {
  W <- Window(X)
  if (!is.multitype(X)) return(generate(npoints(X), W))
  parts <- lapply(levels(marks(X)), function(k) generate(sum(marks(X) == k), W))
  names(parts) <- levels(marks(X))
  do.call(superimpose, parts)
}
uniform <- function(n, W) runifpoint(n, W)
poisson_disk <- function(n, W) {
  d <- 0.7 * sqrt(2 * area(W) / (sqrt(3) * max(n, 1)))
  rSSI(d, n, W, giveup = 100000)
}

for (process in processes) {
  dir <- file.path(out_dir, process)
  dir.create(dir, showWarnings = FALSE, recursive = TRUE)
  for (d in seq(first, length.out = draws)) {
    set.seed(1000 * match(process, all_processes) + d)
    ex <- simulate(process, square(1))
    same <- simulate(process, square(U))
    stem <- file.path(dir, sprintf("d%03d", d))
    write_plain(ex, paste0(stem, "_exemplar.txt"))
    write_plain(same, paste0(stem, "_same.txt"))
    write_plain(same_counts(same, uniform), paste0(stem, "_csr.txt"))
    write_plain(same_counts(same, poisson_disk), paste0(stem, "_ssi.txt"))
    if (is.multitype(same)) write_plain(rlabel(same), paste0(stem, "_relabel.txt"))
  }
  cat(process, ":", draws, "draws in", dir, "\n")
}
