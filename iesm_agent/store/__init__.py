"""The map store: model, `.iesm` file format, importers and the `MapStore` tool surface."""

from .fileformat import load_map, save_map
from .mapstore import MapStore
from .model import GridSpec, Instance, InstanceGrid, Room, SceneMap
from .refs import open_map, resolve_map_path

__all__ = ["SceneMap", "Instance", "Room", "GridSpec", "InstanceGrid", "MapStore", "load_map", "save_map", "open_map",
           "resolve_map_path"]
