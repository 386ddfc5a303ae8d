"""Per-keyframe exposure and white balance brought to the scene's own (colours.constancy) and its
use by the offline captioner."""

from __future__ import annotations

import numpy as np

from iesm_agent.captioning.offline import measured_colour
from iesm_agent.captioning.views import Crop, Geometry, InstanceView
from iesm_agent.colours import colour_family
from iesm_agent.colours.constancy import frame_illuminant, relative_gains
from iesm_agent.store.model import Instance


def _room(albedo_object, exposure: float, balance=(1.0, 1.0, 1.0), cast=(1.0, 0.95, 0.85)) -> np.ndarray:
    """A 60 x 80 frame: a white ceiling, a cream wall, a darker floor and a 20 x 20 object under
    light of colour `cast`, times the camera's exposure and per-channel white balance for this frame."""
    frame = np.empty((60, 80, 3))
    frame[:8] = (250, 250, 250)
    frame[8:30] = (235, 230, 205)
    frame[30:] = (150, 110, 75)
    frame[20:40, 30:50] = albedo_object
    return np.clip(frame * np.array(cast) * exposure * np.array(balance), 0, 255).astype(np.uint8)


def test_frames_are_brought_to_the_scene_reference_not_to_grey():
    frames = {0: _room((255, 255, 255), 1.0), 1: _room((255, 255, 255), 0.7, (0.9, 1.0, 1.12)),
              2: _room((255, 255, 255), 0.9, (1.05, 1.0, 0.95))}
    gains = relative_gains({f: frame_illuminant(rgb) for f, rgb in frames.items()})
    balanced = {f: np.clip(rgb * gains[f], 0, 255) for f, rgb in frames.items()}
    wall = {f: b[10, 10] for f, b in balanced.items()}
    raw_spread = np.ptp(np.stack([rgb[10, 10].astype(float) for rgb in frames.values()]), axis=0).max()
    spread = np.ptp(np.stack(list(wall.values())), axis=0).max()
    assert raw_spread > 50 and spread < 8                 # one wall, one colour across keyframes
    assert wall[0][0] - wall[0][2] > 20                    # the scene's warm light is kept, not greyed


def test_a_frame_without_a_usable_estimate_is_left_as_it_is():
    gains = relative_gains({0: frame_illuminant(np.zeros((10, 10, 3), np.uint8)),
                            1: frame_illuminant(np.full((10, 10, 3), 200, np.uint8))})
    assert np.allclose(gains[0], 1.0) and np.allclose(gains[1], 1.0)
    assert relative_gains({}) == {}


def test_the_captioner_names_a_white_object_white_across_drifting_keyframes():
    white, neutral = (255, 255, 255), (1, 1, 1)
    # the object's three keyframes all drift dark and tinted; the scene's other keyframes do not
    frames = {0: _room(white, 0.6, (0.85, 1.0, 1.2), neutral), 1: _room(white, 0.65, (1.15, 1.0, 0.85), neutral),
              2: _room(white, 0.55, (0.9, 1.0, 1.15), neutral),
              **{f: _room((150, 110, 75), exposure, cast=neutral) for f, exposure in ((3, 0.9), (4, 0.95), (5, 0.88))}}
    mask = np.zeros((60, 80), bool)
    mask[20:40, 30:50] = True
    gains = relative_gains({f: frame_illuminant(rgb) for f, rgb in frames.items()})
    inst = Instance(id=1, label="cabinet")

    def view(with_gains: bool) -> InstanceView:
        crops = [Crop(f, frames[f], mask, gains[f] if with_gains else np.ones(3)) for f in (0, 1, 2)]
        return InstanceView(inst, None, Geometry(0.5, 1.0, 0.5), crops=crops)

    assert colour_family(measured_colour(view(True))) == "white"
    assert colour_family(measured_colour(view(False))) != "white"   # the drift alone turns it grey
