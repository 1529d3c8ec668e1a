# Type stubs of smpl_export (python/smpl_export/__init__.py; docs/python.md).
import os
from typing import Any, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
ArrayLike = Any  # numpy arrays, torch tensors (any device), anything with __array__

class Error(ValueError):
    exit_code: int
    def __init__(self, message: str, exit_code: int = ...) -> None: ...

class UsageError(Error): ...   # exit code 1
class InputError(Error): ...   # exit code 2
class ExportError(Error): ...  # exit code 3
class OutputError(Error): ...  # exit code 4
class Note(UserWarning): ...

class Model:
    path: str
    @property
    def family(self) -> str: ...  # "smpl", "smplh", "smplx", "mano"
    @property
    def joint_names(self) -> list[str]: ...  # K
    @property
    def parents(self) -> list[int]: ...  # K, parents[0] == -1
    @property
    def num_betas(self) -> int: ...
    @property
    def num_expression(self) -> int: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_joints(self) -> int: ...
    @property
    def name(self) -> str: ...
    def forward(self, betas: Optional[ArrayLike], poses: ArrayLike, trans: Optional[ArrayLike] = ...,
                expression: Optional[ArrayLike] = ..., dtype: Union[str, type] = ...
                ) -> Tuple[npt.NDArray[np.floating], npt.NDArray[np.floating]]: ...
        # (T,V,3) vertices, (T,K,3) joints, metres

class Motion:
    @property
    def rotations(self) -> npt.NDArray[np.float64]: ...  # (T,K,3,3)
    @property
    def trans(self) -> npt.NDArray[np.float64]: ...  # (T,3) metres
    @property
    def betas(self) -> Optional[npt.NDArray[np.float64]]: ...  # (B,)
    @property
    def expression(self) -> Optional[npt.NDArray[np.float64]]: ...  # (T,E)
    @property
    def fps(self) -> float: ...
    @property
    def layout(self) -> str: ...
    @property
    def notes(self) -> list[str]: ...
    @property
    def track(self) -> str: ...
    @property
    def gender(self) -> str: ...
    @property
    def joint_names(self) -> list[str]: ...
    @property
    def name(self) -> str: ...
    @property
    def num_frames(self) -> int: ...
    source: str
    reading_options: list[str]

def load_model(path: Union[str, os.PathLike[str]]) -> Model: ...
def read_motion(motion: Union[str, os.PathLike[str], Mapping[str, Any]], model: Optional[Model] = ...,
                track: Optional[Union[str, int]] = ..., name: str = ..., **options: Any) -> Motion: ...
def export(model: Model, motion: Union[None, str, os.PathLike[str], Motion, Mapping[str, Any]] = ...,
           betas: Optional[ArrayLike] = ..., format: str = ...,
           out: Optional[Union[str, os.PathLike[str]]] = ..., **options: Any) -> Union[bytes, str]: ...
def cli(args: Sequence[Union[str, os.PathLike[str]]]) -> int: ...
