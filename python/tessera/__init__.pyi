"""Type stubs of tessera (the extension tessera._tessera, re-exported by the package)."""
from typing import Callable, Dict, Literal, Optional, Union

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
                 progress: Progress = None, min_patch_fraction: float = 0.375) -> None: ...
    def synthesize(self, width: int, height: int, x: int = 0, y: int = 0, seed: int = 0, threads: int = 0,
                   progress: Progress = None, seams: Optional[Literal["feather", "cut"]] = None,
                   out: Optional[Image] = None, fallback: Literal["sets", "estimate", "overlap"] = "sets",
                   fallback_budget: int = 8, stats: Optional[Dict[str, float]] = None,
                   feather_width: int = 5) -> Image:
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

# ---- Wang tiles (Cohen et al. 2003) ---------------------------------------------------------------

Coloring = Union[Literal["hash", "scanline", "periodic"], npt.NDArray[np.integer]]

def build_wang_tiles(exemplar: Image, *, tile_size: int = 64, horizontal_colors: int = 2, vertical_colors: int = 2,
                     mip_levels: int = 0, overlap: int = 0, patch_size: int = 0, border: int = 0,
                     tolerance: float = 0.1, boundary_weight: float = 64.0, min_candidates: int = 4, seed: int = 1,
                     threads: int = 0, progress: Progress = None) -> "WangTileSet":
    """The complete Wang tile set (horizontal_colors**2 * vertical_colors**2 tiles) of an exemplar."""

class WangTileSet:
    """Square image tiles with edge colours; immutable."""
    @staticmethod
    def load(directory: str, dtype: Optional[Literal["uint8", "uint16", "float32"]] = None,
             channels: int = 0) -> "WangTileSet":
        """Reads a tile directory (tiles.json + tile_<i>.png)."""
    def save(self, directory: str) -> None:
        """Writes DIR/tiles.json and DIR/tile_<i>.png."""
    @property
    def tile_size(self) -> int: ...
    @property
    def num_tiles(self) -> int: ...
    def __len__(self) -> int: ...
    @property
    def horizontal_colors(self) -> int: ...
    @property
    def vertical_colors(self) -> int: ...
    @property
    def shared_border(self) -> int: ...
    @property
    def exact_mip_levels(self) -> int: ...
    @property
    def dtype(self) -> np.dtype: ...
    @property
    def channels(self) -> int: ...
    @property
    def edges(self) -> npt.NDArray[np.int32]:
        """num_tiles x 4 edge colours [north, east, south, west]."""
    def tile(self, index: int) -> Image: ...
    def compose(self, width: int, height: int, x: int = 0, y: int = 0, *, coloring: Coloring = "hash",
                seed: int = 1, variant_seed: int = 1, period: int = 4, outline: bool = False,
                threads: int = 0) -> Image:
        """The window (x, y, width, height) of the plane tiled through ``coloring``."""
    def atlas(self, layout: Literal["edge_ordered", "padded"] = "edge_ordered", mip_levels: int = 0,
              padding: int = 0) -> dict:
        """The set packed into one texture: image, tile_size, padding, slot_size, mip_levels, slot_col, slot_row."""

# ---- fabric (paper 001) --------------------------------------------------------------------------

def cat_map_period(n: int, a: int = 1, b: int = 1) -> int:
    """Period of the cat map [1 a; b ab+1] on an n x n image (n in [1, 2**62])."""

def cat_map(image: Image, steps: int, a: int = 1, b: int = 1,
            non_square: Literal["reject", "centered_square", "square_tiles"] = "reject", tile_size: int = 0,
            threads: int = 0) -> Image:
    """``steps`` cat-map iterations (negative: inverse) of a square image; a new array of its dtype."""

def life_perturbation(image: Image, generations: int = 1, live_count: int = 3, live_exact: bool = True,
                      dead_count: int = 6, crowding_count: int = 0,
                      live_test: Literal["brighter_than_pixel", "above_threshold"] = "brighter_than_pixel",
                      threshold: float = 0.5, seed: int = 1, threads: int = 0, progress: Progress = None) -> Image:
    """The game-of-life luminance perturbation of paper 001 (hue and alpha kept)."""

def fabric_presets() -> tuple[str, str, str, str]:
    """('flannel', 'twill', 'linen', 'tweed')."""

def make_fabric(preset: Literal["flannel", "twill", "linen", "tweed"], width: int = 256, height: int = 256,
                tile_size: int = 0, seed: int = 1, threads: int = 0, progress: Progress = None) -> Image:
    """A preset fabric, height x width x 3 uint8, periodic with side tile_size (0: max(width, height))."""

def fabric_from_image(source: Image, width: int, height: int, iterations: int = 60, a: int = 1, b: int = 1,
                      generations: int = 0, seed: int = 1, tile_size: int = 0,
                      fit: Literal["reject", "centered_square", "crop_or_repeat"] = "reject", threads: int = 0,
                      progress: Progress = None) -> Image:
    """A fabric from any source image: cat map, optional perturbation, tiled over height x width."""

# ---- meshes: V float64 (n x 3), F int32 / int64 (m x 3); results are int64 --------------------------

Vertices = npt.NDArray[np.float64]
Faces = npt.NDArray[Union[np.int32, np.int64]]
Mesh = tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]

def read_mesh(path: str) -> Mesh:
    """Reads an OBJ, OFF or PLY triangle mesh."""

def write_mesh(path: str, vertices: Vertices, faces: Faces) -> None:
    """Writes an OBJ, OFF or PLY file chosen by extension."""

def render_mesh_preview(vertices: Vertices, faces: Faces, width: int = 800, height: int = 600,
                        azimuth_degrees: float = -60.0, elevation_degrees: float = 45.0,
                        grid_spacing: float = 0.0, threads: int = 0) -> npt.NDArray[np.uint8]:
    """A shaded height x width x 3 uint8 picture of a mesh."""

# ---- terrain (paper 003) -------------------------------------------------------------------------

def make_terrain(cells_x: int = 128, cells_y: int = 128, size_x: float = 100.0, size_y: float = 100.0,
                 height: float = 14.0, feature_size: float = 0.4, octaves: int = 6, seed: int = 1,
                 threads: int = 0) -> Mesh:
    """A fractal heightfield mesh (z up) centred on 0."""

def render_terrain_frame(vertices: Vertices, faces: Faces, exemplar: Image, width: int = 640, height: int = 360,
                         camera: Optional[Literal["grazing", "oblique", "overview"]] = None,
                         eye: tuple[float, float, float] = (0, -60, 20),
                         target: tuple[float, float, float] = (0, 0, 0),
                         up: tuple[float, float, float] = (0, 0, 1), fov_y_degrees: float = 60.0,
                         near: float = 0.01, far: float = 1000.0, min_scale: float = 0.5, seed: int = 1,
                         shading: Literal["texture", "scale_field", "regions"] = "texture", feather: float = 3.0,
                         sun: tuple[float, float, float] = (0, 0, 0), ambient: float = 0.35, threads: int = 0,
                         progress: Progress = None) -> dict:
    """One synthesized frame: {'image', 'level', 'scale', 'distance', 'levels', 'visible_faces'}."""

# ---- geometry (paper 000) ------------------------------------------------------------------------

def mesh_exemplar(kind: Literal["rings", "chain_mail", "stones", "weave"] = "rings", size: float = 8.0,
                  seed: int = 1) -> Mesh:
    """A procedural geometric-texture exemplar over [0, size]^2."""

def mesh_quilt(vertices: Vertices, faces: Faces, width: float, height: float, seed: int = 0, threads: int = 0,
               progress: Progress = None) -> Mesh:
    """Mesh quilting of a width x height geometric texture."""

class GeometricTileSet:
    """A complete set of geometric Wang tiles."""
    @staticmethod
    def build(vertices: Vertices, faces: Faces, tile_size: float, horizontal_colors: int = 2,
              vertical_colors: int = 2, edge_height: float = 0.0, seed: int = 0, threads: int = 0,
              progress: Progress = None) -> "GeometricTileSet": ...
    @staticmethod
    def load(directory: str, tolerance: float = 1e-6) -> "GeometricTileSet": ...
    def save(self, directory: str) -> None: ...
    @property
    def tile_size(self) -> float: ...
    @property
    def edge_height(self) -> float: ...
    @property
    def horizontal_colors(self) -> int: ...
    @property
    def vertical_colors(self) -> int: ...
    @property
    def num_tiles(self) -> int: ...
    @property
    def edges(self) -> npt.NDArray[np.int32]:
        """(tiles x 4) edge colours (north, east, south, west)."""
    def tile(self, index: int) -> Mesh: ...
    def tile_plane(self, cols: int, rows: int, seed: int = 1, origin_col: int = 0, origin_row: int = 0,
                   threads: int = 0) -> Mesh:
        """A welded cols x rows plane by a hash colouring."""

# ---- surface ---------------------------------------------------------------------------------------

def remesh(vertices: Vertices, faces: Faces, edge_length: float = 0.0, edges_across: int = 64,
           feature_angle: float = 40.0, iterations: int = 10) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], dict]:
    """Isotropic remeshing (creases kept): (V, F, stats)."""

class PolycubeMap:
    """The polycube map of a closed triangle mesh, with its quad layout."""
    @staticmethod
    def build(vertices: Vertices, faces: Faces, tile_size: float = 0.0, tiles_across: int = 8,
              compactness: float = 1.0, distortion_retries: int = 0, threads: int = 0) -> "PolycubeMap": ...
    @staticmethod
    def load(path: str) -> "PolycubeMap": ...
    def save(self, path: str) -> None: ...
    @property
    def tile_size(self) -> float: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def faces(self) -> npt.NDArray[np.int64]: ...
    @property
    def polycube_positions(self) -> npt.NDArray[np.float64]: ...
    @property
    def labels(self) -> npt.NDArray[np.uint8]:
        """Per face: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z."""
    @property
    def face_chart(self) -> npt.NDArray[np.int64]: ...
    @property
    def face_origin(self) -> npt.NDArray[np.int64]:
        """Input face of every base face when the base is a refinement of the input; else empty."""
    @property
    def charts(self) -> list[dict]: ...
    @property
    def num_quads(self) -> int: ...
    @property
    def quad_corners(self) -> npt.NDArray[np.int64]: ...
    @property
    def quad_neighbors(self) -> npt.NDArray[np.int64]: ...
    @property
    def quad_chart(self) -> npt.NDArray[np.int64]: ...
    @property
    def num_corners(self) -> int: ...
    @property
    def num_edges(self) -> int: ...
