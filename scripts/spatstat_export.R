# Exports point patterns of R's spatstat.data (installed from Debian: r-cran-spatstat.data)
# into ppsynth's plain point text (core/formats/plain_text_format.hpp). The repository ships
# this script, not the data: spatstat.data is GPL, and each user makes the files from their own
# installed package.
#
#   Rscript scripts/spatstat_export.R OUT_DIR [NAME ...]
#     NAME: a data set of spatstat.data (default: cells redwood japanesepines swedishpines
#           amacrine longleaf); "all" exports every point pattern with a rectangular window
#           and no marks, factor marks or numeric marks.
#
# Each pattern becomes OUT_DIR/NAME.txt:
#   - the window shifted to the origin and scaled by one factor for both axes so that its
#     shorter side is 1: the aspect ratio is kept, and the exemplar covers the unit square
#     that the Gabor maps sample (a 96 x 100 decimetre window becomes 1 x 1.042);
#   - factor marks (multitype) become the class column, classes 0..K-1 in the order of the
#     factor's levels (a "# classes" comment names them);
#   - numeric marks become an attribute column named "mark" (its unit in a comment);
#   - comment lines name the source, its window and unit, and the scale factor: a distance
#     r in the file is r / scale in the data set's units.
# Refuses (non-zero exit, nothing written for that name) a data set that is not a point
# pattern, whose window is not a rectangle, or whose marks are a data frame.
suppressPackageStartupMessages({
  library(spatstat.data)
  library(spatstat.geom)
})

args <- commandArgs(trailingOnly = TRUE)
if (length(args) < 1) {
  cat("usage: Rscript scripts/spatstat_export.R OUT_DIR [NAME ...|all]\n", file = stderr())
  quit(status = 2)
}
out_dir <- args[1]
names <- if (length(args) > 1) args[-1] else
  c("cells", "redwood", "japanesepines", "swedishpines", "amacrine", "longleaf")

exportable <- function(X) {
  is.ppp(X) && X$window$type == "rectangle" &&
    (!is.marked(X) || is.factor(marks(X)) || is.numeric(marks(X)))
}

if (identical(names, "all")) {
  all <- data(package = "spatstat.data")$results[, "Item"]
  names <- Filter(function(n) {
    X <- tryCatch(get(n, envir = asNamespace("spatstat.data")), error = function(e) NULL)
    !is.null(X) && exportable(X)
  }, all)
}

dir.create(out_dir, showWarnings = FALSE, recursive = TRUE)
failed <- FALSE
for (name in names) {
  X <- tryCatch(get(name, envir = asNamespace("spatstat.data")), error = function(e) NULL)
  if (is.null(X)) {
    cat(sprintf("spatstat_export: '%s' is not a data set of spatstat.data\n", name), file = stderr())
    failed <- TRUE
    next
  }
  if (!exportable(X)) {
    cat(sprintf("spatstat_export: '%s' is not a point pattern with a rectangular window and no, factor or numeric marks\n",
                name), file = stderr())
    failed <- TRUE
    next
  }
  xr <- X$window$xrange
  yr <- X$window$yrange
  scale <- 1 / min(diff(xr), diff(yr))
  x <- (X$x - xr[1]) * scale
  y <- (X$y - yr[1]) * scale
  W <- diff(xr) * scale
  H <- diff(yr) * scale
  # Rounding may push a point on the far edge a hair outside; the reader refuses that.
  x <- pmin(pmax(x, 0), W)
  y <- pmin(pmax(y, 0), H)
  u <- unitname(X)
  unit <- if (is.null(u)) "units" else trimws(paste(summary(u)$plural, summary(u)$explain))
  lines <- c("# ppsynth points",
             sprintf("# source: spatstat.data %s %s (%d points), exported by scripts/spatstat_export.R",
                     name, as.character(packageVersion("spatstat.data")), npoints(X)),
             sprintf("# original window [%.17g, %.17g] x [%.17g, %.17g] %s; coordinates = (original - corner) * %.17g",
                     xr[1], xr[2], yr[1], yr[2], unit, scale),
             sprintf("# domain 0 0 %.17g %.17g", W, H))
  cols <- "# x y"
  body <- sprintf("%.17g %.17g", x, y)
  if (is.marked(X)) {
    m <- marks(X)
    if (is.factor(m)) {
      lines <- c(lines, paste0("# classes ", paste(sprintf("%d=%s", seq_along(levels(m)) - 1, levels(m)), collapse = " ")))
      cols <- paste(cols, "class")
      body <- paste(body, as.integer(m) - 1L)
    } else {
      lines <- c(lines, "# mark: the data set's numeric marks, unscaled")
      cols <- paste(cols, "mark")
      body <- paste(body, sprintf("%.17g", m))
    }
  }
  path <- file.path(out_dir, paste0(name, ".txt"))
  tmp <- paste0(path, ".tmp")
  writeLines(c(lines, cols, body), tmp)
  file.rename(tmp, path)
  cat(sprintf("%s: %d points, domain %.4g x %.4g -> %s\n", name, npoints(X), W, H, path))
}
if (failed) quit(status = 1)
