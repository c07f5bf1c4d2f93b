"""Type stubs of the native module (python/src/lib.rs)."""

from typing import List, Optional, Tuple

import numpy as np
import numpy.typing as npt

class TrajverifyError(ValueError): ...

def hermite_f64(
    start: npt.NDArray[np.float64], end: npt.NDArray[np.float64], width: float
) -> npt.NDArray[np.float64]: ...
def natural_spline_f64(
    t: npt.NDArray[np.float64], z: npt.NDArray[np.float64], at: npt.NDArray[np.float64]
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def run(algorithm: str, input: str, scalar: Optional[str] = None) -> str: ...
def verify(out: str, papers: Optional[List[str]] = None) -> str: ...
