"""tessera: texture synthesis over NumPy arrays.

Images are NumPy arrays of shape H x W x C (or H x W for one channel) with dtype uint8, uint16 or
float32 and C = 1 to 4; every function returning an image returns H x W x C (three dimensions, also
for C = 1). Errors raise tessera.Error subclasses that carry the library's message (InvalidArgument
is a ValueError, ParseError a ValueError, IOError an OSError, ...). Long calls release the GIL, take
``threads`` (0: all cores) and an optional ``progress`` callable, and stop on Ctrl-C.
"""

from ._tessera import *  # noqa: F401,F403
from ._tessera import __version__  # noqa: F401
from . import _tessera as _ext

__all__ = sorted(name for name in dir(_ext) if not name.startswith("_"))
