"""Point sets as NumPy arrays, and reading and writing them.

A :class:`PointSet` is ``positions`` (N, 2) float64, ``classes`` (N,) int64 with dense ids
0..K-1, ``attributes`` (N, A) float64 named by ``attribute_names`` (a ``"radius"`` column makes
a disk pattern), a rectangular ``domain`` (x0, y0, x1, y1), ``periodic`` and the file labels of
the classes (``class_labels``, e.g. 1000, 2000 in the Gabor paper's files).

:func:`read` and :func:`write` know every format of the command (the Gabor paper's integers,
Point-Synthesis pixels, this project's plain text and JSON) plus NumPy's ``.npy`` and ``.npz``
(the published Gabor code keeps its initializations as ``.npz`` with the positions under
``"x"``). Writes are atomic (a temporary file renamed) and never replace an existing file
unless ``overwrite=True``.
"""
from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np

from . import _ppsynth as _native

__all__ = ["PointSet", "read", "write", "generate", "generators"]


@dataclass
class PointSet:
    """N points with classes and attributes in a rectangular domain.

    Only ``positions`` is required; the other fields default to one class, no attributes,
    the unit square.

    Attributes
    ----------
    positions : numpy.ndarray, shape (N, 2), float64
        The points.
    classes : numpy.ndarray, shape (N,), int64
        Dense class ids 0..K-1 (default: all 0).
    attributes : numpy.ndarray, shape (N, A), float64
        Per-point attributes, one column per name (default: none).
    attribute_names : sequence of str
        The attribute columns' names; ``"radius"`` makes a disk pattern.
    domain : (x0, y0, x1, y1)
        The rectangle the points lie in (default: the unit square).
    periodic : bool
        Whether the domain is a torus.
    class_labels : list of int
        The labels the file gave its classes, one per class id (default: none).

    Examples
    --------
    >>> ps = PointSet(np.random.default_rng(1).random((100, 2)))
    >>> len(ps), ps.num_classes
    (100, 1)
    """

    positions: np.ndarray
    classes: Optional[np.ndarray] = None
    attributes: Optional[np.ndarray] = None
    attribute_names: Sequence[str] = ()
    domain: Sequence[float] = (0.0, 0.0, 1.0, 1.0)
    periodic: bool = False
    class_labels: Sequence[int] = field(default_factory=list)

    def __post_init__(self):
        self.positions = np.ascontiguousarray(self.positions, dtype=np.float64)
        if self.positions.ndim != 2 or self.positions.shape[1] != 2:
            raise ValueError(f"positions: expected an (N, 2) array, got shape {self.positions.shape}")
        n = self.positions.shape[0]
        if self.classes is None:
            self.classes = np.zeros(n, dtype=np.int64)
        else:
            c = np.asarray(self.classes)
            if c.ndim != 1 or c.shape[0] != n:
                raise ValueError(f"classes: expected an ({n},) integer array, got shape {c.shape}")
            if c.size and not np.all(np.equal(np.mod(c, 1), 0)):
                raise ValueError("classes: expected whole numbers (dense class ids 0..K-1)")
            self.classes = np.ascontiguousarray(c, dtype=np.int64)
        self.attribute_names = [str(a) for a in self.attribute_names]
        if self.attributes is None:
            self.attributes = np.zeros((n, len(self.attribute_names)), dtype=np.float64)
        self.attributes = np.ascontiguousarray(self.attributes, dtype=np.float64)
        if self.attributes.ndim == 1 and len(self.attribute_names) == 1:
            self.attributes = self.attributes.reshape(n, 1)
        if self.attributes.shape != (n, len(self.attribute_names)):
            raise ValueError(f"attributes: expected shape ({n}, {len(self.attribute_names)}) "
                             f"(one column per attribute name), got {self.attributes.shape}")
        self.domain = tuple(float(v) for v in self.domain)
        if len(self.domain) != 4:
            raise ValueError("domain: expected (x0, y0, x1, y1)")
        self.periodic = bool(self.periodic)
        self.class_labels = [int(v) for v in self.class_labels]

    def __len__(self) -> int:
        return self.positions.shape[0]

    @property
    def num_classes(self) -> int:
        """K = 1 + the largest class id (0 for an empty set)."""
        return int(self.classes.max()) + 1 if len(self) else 0

    def attribute(self, name: str) -> np.ndarray:
        """The column of attribute ``name`` (a view)."""
        try:
            return self.attributes[:, self.attribute_names.index(name)]
        except ValueError:
            raise KeyError(f"no attribute '{name}' (attributes: {', '.join(self.attribute_names) or 'none'})") from None

    def subset_class(self, k: int) -> "PointSet":
        """The points of class ``k`` (class ids kept)."""
        m = self.classes == k
        return PointSet(self.positions[m], self.classes[m], self.attributes[m], self.attribute_names,
                        self.domain, self.periodic, self.class_labels)

    def validate(self, source: str = "points") -> None:
        """Raises ValueError naming the first point that synthesis cannot take: a non-finite
        coordinate, a point outside the domain, a radius <= 0, an empty class."""
        _native.validate(self._to_native(), source)

    def _to_native(self) -> dict:
        return {"positions": self.positions, "classes": self.classes, "attributes": self.attributes,
                "attribute_names": list(self.attribute_names), "domain": self.domain,
                "periodic": self.periodic, "class_labels": list(self.class_labels)}

    @classmethod
    def _from_native(cls, d: dict) -> "PointSet":
        return cls(d["positions"], d["classes"], d["attributes"], d["attribute_names"], d["domain"],
                   d["periodic"], d["class_labels"])

    def __repr__(self) -> str:
        attrs = f", attributes {self.attribute_names}" if self.attribute_names else ""
        return (f"PointSet({len(self)} points, {self.num_classes} classes{attrs}, "
                f"domain {self.domain}{', periodic' if self.periodic else ''})")


def _as_points(x, what: str) -> PointSet:
    """A PointSet, an (N, 2) array or a file name -> PointSet."""
    if isinstance(x, PointSet):
        return x
    if isinstance(x, (str, os.PathLike)):
        return read(x)
    if isinstance(x, np.ndarray):
        return PointSet(x)
    raise TypeError(f"{what}: expected a PointSet, an (N, 2) array or a file name, not {type(x).__name__}")


def _numpy_kind(path: str) -> Optional[str]:
    ext = os.path.splitext(path)[1].lower()
    return ext[1:] if ext in (".npy", ".npz") else None


def read(path, format: Optional[str] = None, scaling: str = "per-axis",
         attribute_names: Optional[Sequence[str]] = None) -> PointSet:
    """Reads a point file.

    Parameters
    ----------
    path : str or os.PathLike
        The file; ``"shared:data/..."`` names a file of the shared data folder.
    format : str, optional
        None detects it, as the command does ("gabor", "point-synthesis", "plain", "json");
        ``.npy`` and ``.npz`` files are read by NumPy.
    scaling : str
        How Point-Synthesis pixel coordinates reach the unit square: "per-axis" (as
        published) or "uniform" (aspect kept).
    attribute_names : sequence of str, optional
        Names for the attribute columns of formats whose files do not name them.

    Returns
    -------
    PointSet

    Raises
    ------
    FileNotFoundError
        A missing file.
    ValueError
        Anything else, naming the file and line.
    """
    path = os.fspath(path)
    kind = _numpy_kind(path)
    if kind is None:
        return PointSet._from_native(
            _native.read_points(path, format or "auto", scaling, list(attribute_names or [])))
    real = _native.resolve_data_path(path)
    _native.check_input_file(real)  # a regular file within the size bound: a FIFO would block np.load
    ps = _read_npz(real) if kind == "npz" else _read_npy(real)
    if attribute_names is not None:
        if len(attribute_names) != len(ps.attribute_names):
            raise ValueError(f"{path}: attribute_names: {len(attribute_names)} names for "
                             f"{len(ps.attribute_names)} attribute columns")
        ps.attribute_names = list(attribute_names)
    ps.validate(path)
    return ps


def _read_npz(path: str) -> PointSet:
    # NumPy raises what its zip and format readers raise (BadZipFile, EOFError, KeyError, ...):
    # every one is this file's flaw, reported as the package's ValueError naming it.
    try:
        with np.load(path, allow_pickle=False) as z:
            arrays = {k: z[k] for k in z.files}
    except Exception as e:
        raise ValueError(f"{path}: not a readable .npz file ({type(e).__name__}: {e})") from None
    key = "x" if "x" in arrays else "positions" if "positions" in arrays else None
    if key is None:
        raise ValueError(f"{path}: no positions (expected an array 'x' of shape (N, 2), as the published code writes)")
    known = {"x", "positions", "classes", "attributes", "attribute_names", "domain", "periodic", "class_labels"}
    unknown = sorted(set(arrays) - known)
    if unknown:
        raise ValueError(f"{path}: unknown arrays {unknown} (known: {sorted(known)})")
    try:
        return PointSet(arrays[key], arrays.get("classes"), arrays.get("attributes"),
                        [str(s) for s in arrays.get("attribute_names", [])],
                        arrays.get("domain", (0.0, 0.0, 1.0, 1.0)), bool(arrays.get("periodic", False)),
                        [int(v) for v in arrays.get("class_labels", [])])
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None


def _read_npy(path: str) -> PointSet:
    try:
        a = np.load(path, allow_pickle=False)
    except Exception as e:
        raise ValueError(f"{path}: not a readable .npy file ({type(e).__name__}: {e})") from None
    if not isinstance(a, np.ndarray):  # an .npz under an .npy name loads as an archive
        raise ValueError(f"{path}: not an .npy array (an .npz archive?)")
    if a.ndim != 2 or a.shape[1] < 2:
        raise ValueError(f"{path}: expected an (N, 2) array of positions or (N, 3 + A) of x, y, class, "
                         f"attributes; got shape {a.shape}")
    try:
        a = a.astype(np.float64)
        if a.shape[1] == 2:
            return PointSet(a)
        return PointSet(a[:, :2], a[:, 2], a[:, 3:], [f"attr{i}" for i in range(a.shape[1] - 3)])
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None


def write(points: PointSet, path, format: Optional[str] = None, overwrite: bool = False) -> None:
    """Writes a point file, atomically (a temporary file beside it, then renamed).

    Parameters
    ----------
    points : PointSet or array_like of shape (N, 2)
        What to write.
    path : str or os.PathLike
        The file.
    format : str, optional
        None chooses by extension (``.json`` JSON, ``.npy``/``.npz`` NumPy, otherwise this
        project's plain text, which reads back bit-exactly), or "gabor", "point-synthesis",
        "plain", "json". ``.npz`` keeps everything (positions under ``"x"`` as the published
        code reads them); ``.npy`` keeps positions, classes and attribute values (not their
        names).
    overwrite : bool
        Replace an existing file.

    Raises
    ------
    FileExistsError
        The file exists and ``overwrite`` is False.
    ValueError
        What :func:`read` would refuse is never written: a point set that fails
        :meth:`PointSet.validate` (a non-finite coordinate, a point outside the domain, a
        radius <= 0, an empty class, no points); the file stays as it was.
    """
    path = os.fspath(path)
    points = _as_points(points, "points")
    points.validate(path)
    if os.path.lexists(path) and not overwrite:
        raise FileExistsError(f"{path}: exists; pass overwrite=True to replace it")
    kind = _numpy_kind(path) if format is None else None
    if kind is None:
        _native.write_points(points._to_native(), path, format or "auto")
        return
    if os.path.isdir(path):
        raise IsADirectoryError(f"{path}: is a directory")
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=os.path.basename(path) + ".tmp-", suffix="." + kind, dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            if kind == "npz":
                np.savez(f, x=points.positions, classes=points.classes, attributes=points.attributes,
                         attribute_names=np.array(points.attribute_names, dtype=np.str_),
                         domain=np.array(points.domain), periodic=np.array(points.periodic),
                         class_labels=np.array(points.class_labels, dtype=np.int64))
            else:
                if points.num_classes <= 1 and not points.attribute_names:
                    table = points.positions
                else:
                    table = np.column_stack([points.positions, points.classes.astype(np.float64), points.attributes])
                np.save(f, table)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def generate(name: str, n: int, seed: int = 1, domain: Sequence[float] = (0.0, 0.0, 1.0, 1.0),
             periodic: bool = False, **params) -> PointSet:
    """N points of a classic point process, as ``ppsynth generate``; same arguments, same points.

    Parameters
    ----------
    name : str
        One of :func:`generators`: "uniform", "poisson_disk", "best_candidate",
        "jittered_grid", ...
    n : int
        How many points.
    seed : int
        The random seed.
    domain : (x0, y0, x1, y1)
        The rectangle to fill.
    periodic : bool
        Distances on the torus (for the processes that keep points apart).
    **params
        The generator's parameters (defaults: ``generators()[name]["defaults"]``).

    Returns
    -------
    PointSet
    """
    spec = {"type": name, **params}
    return PointSet._from_native(_native.generate(spec, int(n), int(seed), tuple(domain), bool(periodic)))


def generators() -> dict:
    """Every generator with its description and default parameters.

    Returns
    -------
    dict
        name -> ``{"description": str, "defaults": dict, "bounds": dict}``.
    """
    return _native.defaults().get("generator", {})
