# ppsynth's plain point text (core/formats/plain_text_format.hpp) read into and written from
# spatstat's ppp, for the R scripts beside this file and docs/lab/verdict/'s (source()d, not run).
#
# read_plain(path): the "# domain" rectangle (default the unit square), the "# x y ..." header's
# columns; a "class" column becomes factor marks (multitype), a column "mark" numeric marks
# (when both are there, the class wins and "mark" is left in attr(X, "table")). attr(X, "table")
# holds every column as read.
# write_plain(X, path, comment): "# ppsynth points", the comment lines, "# domain", the points
# with a class column for a multitype X (classes 0..K-1 in the order of its levels).
suppressPackageStartupMessages(library(spatstat.geom))

read_plain <- function(path) {
  lines <- readLines(path)
  dom <- grep("^#[[:space:]]*domain", lines, value = TRUE)
  box <- if (length(dom)) as.numeric(strsplit(trimws(sub("^#[[:space:]]*domain", "", dom[1])), "[[:space:]]+")[[1]][1:4]) else c(0, 0, 1, 1)
  hdr <- grep("^#[[:space:]]*x[[:space:]]+y", lines, value = TRUE)
  cols <- if (length(hdr)) strsplit(trimws(sub("^#", "", hdr[1])), "[[:space:]]+")[[1]] else c("x", "y")
  tab <- read.table(text = lines[!grepl("^#", lines) & nzchar(trimws(lines))], col.names = cols)
  X <- ppp(tab$x, tab$y, window = owin(c(box[1], box[3]), c(box[2], box[4])), check = FALSE)
  if ("class" %in% cols) X <- X %mark% factor(tab$class) else if ("mark" %in% cols) X <- X %mark% tab$mark
  attr(X, "table") <- tab
  X
}

write_plain <- function(X, path, comment = character()) {
  W <- Window(X)
  lines <- c("# ppsynth points", if (length(comment)) paste("#", comment),
             sprintf("# domain %.17g %.17g %.17g %.17g", W$xrange[1], W$yrange[1], W$xrange[2], W$yrange[2]))
  if (is.multitype(X)) {
    lines <- c(lines, "# x y class", sprintf("%.17g %.17g %d", X$x, X$y, as.integer(marks(X)) - 1L))
  } else {
    lines <- c(lines, "# x y", sprintf("%.17g %.17g", X$x, X$y))
  }
  writeLines(lines, path)
}

