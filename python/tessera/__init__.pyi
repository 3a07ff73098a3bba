"""Type stubs of tessera (the extension tessera._tessera, re-exported by the package)."""
from typing import Callable, Literal, Optional, Union

import numpy as np
import numpy.typing as npt

__version__: str
__all__: list[str]

Image = npt.NDArray[Union[np.uint8, np.uint16, np.float32]]
"""H x W or H x W x C (C = 1-4) array of uint8, uint16 or float32; results are always H x W x C."""
Progress = Optional[Callable[[float], Optional[bool]]]
"""Called with the fraction done (0 to 1); returning False cancels (tessera.Cancelled)."""

class Error(RuntimeError):
    """Base class of tessera's errors; ``code`` names the status code."""
    code: Optional[str]

class InvalidArgument(Error, ValueError): ...
class OutOfRange(Error, IndexError): ...
class SizeOverflow(Error, OverflowError): ...
class IOError(Error, OSError): ...
class ParseError(Error, ValueError): ...
class Unsupported(Error, NotImplementedError): ...
class Cancelled(Error): ...
class NotConverged(Error): ...
class InternalError(Error): ...

def read_png(path: str, max_pixels: int = 268435456) -> Image:
    """A PNG file as H x W x C: uint8 for 8-bit files, uint16 for 16-bit ones."""

def write_png(path: str, image: Image) -> None:
    """Writes an image as PNG (uint8: 8-bit; uint16 and float32: 16-bit, floats clamped to [0, 1])."""

def exemplar(kind: Literal["grass", "sand", "rock", "bricks", "cells", "weave", "dots"], width: int = 128,
             height: int = 128, seed: int = 1) -> npt.NDArray[np.uint8]:
    """A procedural H x W x 3 uint8 exemplar (what ``tessera synth --exemplar KIND`` renders)."""

class PatchModel:
    """A patch-synthesis model (paper 002): build once, synthesize any window; picklable."""
    def __init__(self, exemplar: Image, *, patch_width: int = 0, patch_height: int = 0, overlap: int = 0,
                 candidates: int = 8, exact_sets: bool = False, pca_dims: int = 8, pca_samples: int = 384,
                 search_pool: int = 16, refine_iterations: int = 4, seams: bool = False, threads: int = 0,
                 progress: Progress = None) -> None: ...
    def synthesize(self, width: int, height: int, x: int = 0, y: int = 0, seed: int = 0, threads: int = 0,
                   progress: Progress = None, seams: Optional[Literal["feather", "cut"]] = None) -> Image:
        """The width x height window at (x, y) of the unbounded texture of (model, seed)."""
    def save(self) -> bytes:
        """The model as bytes (format version 1)."""
    @staticmethod
    def load(data: bytes, threads: int = 0) -> "PatchModel":
        """A model from save()'s bytes; ParseError / Unsupported for bad bytes or another version."""
    @property
    def dtype(self) -> np.dtype: ...
    @property
    def channels(self) -> int: ...
    @property
    def patch_width(self) -> int: ...
    @property
    def patch_height(self) -> int: ...
    @property
    def overlap(self) -> int: ...
    @property
    def candidates(self) -> int: ...
    @property
    def exact_sets(self) -> bool: ...
    @property
    def pca_dims(self) -> int: ...
    @property
    def pca_samples(self) -> int: ...
    @property
    def search_pool(self) -> int: ...
    @property
    def refine_iterations(self) -> int: ...
    @property
    def seams(self) -> bool: ...
    @property
    def num_patches(self) -> int: ...
    @property
    def memory_bytes(self) -> int: ...
    @property
    def exemplar(self) -> Image: ...

def quilt(exemplar: Image, width: int, height: int, *, patch_size: int = 0, overlap: int = 0,
          tolerance: float = 0.1, seamless: bool = False, seed: int = 1, threads: int = 0,
          progress: Progress = None) -> Image:
    """Image quilting (Efros & Freeman 2001) of a width x height texture."""

def constrained_quilt(image: Image, mask: npt.NDArray[Union[np.bool_, np.uint8]], exemplar: Optional[Image] = None,
                      *, patch_size: int = 0, overlap: int = 0, tolerance: float = 0.1,
                      boundary_weight: float = 64.0, seed: int = 1, threads: int = 0,
                      progress: Progress = None) -> Image:
    """Fills the masked pixels of ``image`` by constrained quilting; other pixels are unchanged."""
