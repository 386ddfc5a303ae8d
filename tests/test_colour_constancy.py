"""Per-keyframe white balance brought to the scene's own (colours.constancy) and its use by the
offline captioner."""

from __future__ import annotations

import numpy as np

from iesm_agent.captioning.offline import measured_colour
from iesm_agent.captioning.views import Crop, Geometry, InstanceView
from iesm_agent.colours import colour_family
from iesm_agent.colours.constancy import relative_gains, white_patch
from iesm_agent.store.model import Instance

WHITE, NEUTRAL = (255, 255, 255), (1.0, 1.0, 1.0)


def _room(albedo_object, exposure: float, balance=NEUTRAL, cast=(1.0, 0.97, 0.92)) -> np.ndarray:
    """A 60 x 80 frame: a white ceiling, a cream wall, a darker floor and a 20 x 20 object under
    light of colour `cast`, times the camera's exposure and per-channel white balance for this frame."""
    frame = np.empty((60, 80, 3))
    frame[:8] = (250, 250, 250)
    frame[8:30] = (235, 230, 205)
    frame[30:] = (150, 110, 75)
    frame[20:40, 30:50] = albedo_object
    return np.clip(frame * np.array(cast) * exposure * np.array(balance), 0, 255).astype(np.uint8)


def _chroma(rgb) -> np.ndarray:
    rgb = np.asarray(rgb, np.float64)
    return rgb / rgb.mean()


def test_frames_are_brought_to_the_scene_white_balance_not_to_grey():
    frames = {0: _room(WHITE, 0.9), 1: _room(WHITE, 0.8, (0.92, 1.0, 1.1)), 2: _room(WHITE, 0.85, (1.06, 1.0, 0.94))}
    gains = relative_gains({f: white_patch(rgb) for f, rgb in frames.items()})
    wall = {f: _chroma(rgb[10, 10] * gains[f]) for f, rgb in frames.items()}
    raw_spread = np.ptp(np.stack([_chroma(rgb[10, 10]) for rgb in frames.values()]), axis=0).max()
    spread = np.ptp(np.stack(list(wall.values())), axis=0).max()
    assert raw_spread > 0.1 and spread < 0.02              # one wall, one chromaticity across keyframes
    assert wall[0][0] - wall[0][2] > 0.15                  # the scene's warm light is kept, not greyed
    # a frame whose bright pixels are all strongly coloured gives no estimate, and is left as it is
    orange = _room((255, 120, 60), 1.0, cast=(1.0, 0.7, 0.5))
    assert not white_patch(orange).any()
    assert np.allclose(relative_gains({**{f: white_patch(rgb) for f, rgb in frames.items()},
                                       3: white_patch(orange)})[3], 1.0)


def test_a_frame_without_a_usable_estimate_is_left_as_it_is():
    gains = relative_gains({0: white_patch(np.zeros((10, 10, 3), np.uint8)),
                            1: white_patch(np.full((10, 10, 3), 200, np.uint8))})
    assert np.allclose(gains[0], 1.0) and np.allclose(gains[1], 1.0)
    assert relative_gains({}) == {}
    assert np.allclose(white_patch(np.zeros((0, 0, 3))), 0.0)


def test_the_captioner_names_a_white_object_white_across_tinted_keyframes():
    # the object's three keyframes all drift blue; the scene's other keyframes do not
    frames = {0: _room(WHITE, 0.85, (0.92, 1.0, 1.1), NEUTRAL), 1: _room(WHITE, 0.8, (0.9, 0.98, 1.08), NEUTRAL),
              2: _room(WHITE, 0.9, (0.93, 1.0, 1.1), NEUTRAL),
              **{f: _room((150, 110, 75), 0.9, cast=NEUTRAL) for f in (3, 4, 5, 6)}}
    mask = np.zeros((60, 80), bool)
    mask[20:40, 30:50] = True
    gains = relative_gains({f: white_patch(rgb) for f, rgb in frames.items()})
    inst = Instance(id=1, label="cabinet")

    def view(with_gains: bool) -> InstanceView:
        crops = [Crop(f, frames[f], mask, gains[f] if with_gains else np.ones(3)) for f in (0, 1, 2)]
        return InstanceView(inst, None, Geometry(0.5, 1.0, 0.5), crops=crops)

    assert colour_family(measured_colour(view(True))) == "white"
    assert colour_family(measured_colour(view(False))) == "blue"    # the drift alone makes it a pale blue
