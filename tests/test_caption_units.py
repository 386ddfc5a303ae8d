"""Colour naming, keyframe selection and the caption reply schema on small hand-made arrays."""

import base64

import numpy as np
import pytest
from pydantic import ValidationError

from iesm_agent.colours import DECLARED_SHADING, OBSERVED_SHADING, ciede2000, colour_name, colour_table, masked_lab, name_lab, rgb_to_lab
from iesm_agent.captioning.keyframes import crop_box, outlined_png, select_keyframes
from iesm_agent.captioning.schema import CaptionReply, CaptionResult
from iesm_agent.errors import IesmError
from iesm_agent.lexicon import load_lexicon


def test_ciede2000_matches_sharma_reference_pairs():
    # Sharma, Wu, Dalal (2005) test data, pairs 1, 7, 13(ish), 33, 17
    a = np.array([[50, 2.6772, -79.7751], [50, 0, 0], [50, 2.5, 0], [2.0776, 0.0795, -1.1350], [50, 2.49, -0.001]])
    b = np.array([[50, 0, -82.7485], [50, -1, 2], [73, 25, -18], [0.9033, -0.0636, -0.5514], [50, -2.49, 0.0009]])
    expected = [2.0425, 2.3669, 27.1492, 0.9082, 7.1792]
    assert ciede2000(a, b) == pytest.approx(expected, abs=1e-4)
    assert ciede2000(b, a) == pytest.approx(expected, abs=1e-4)


def test_table_names_are_words_the_lexicon_reads_as_their_family():
    lex = load_lexicon()
    table = colour_table()
    assert len(table.names) >= 100 and len(set(table.names)) == len(table.names)
    for name, family in zip(table.names, table.families):
        lemmas = [lex.lemma(t) for t in lex.tokens(name)]
        colours = [s.values("color")[0] for s in lex.scan(lemmas) if s.has("color")]
        assert colours and colours[-1] == family, name


@pytest.mark.parametrize("rgb,name", [((0x01, 0x15, 0x3E), "navy"), ((0xE6, 0xDA, 0xA6), "beige"),
                                      ((0x34, 0x1C, 0x02), "dark brown"), ((0xD8, 0xDC, 0xD6), "light grey"),
                                      ((250, 250, 250), "white"), ((3, 3, 3), "black")])
def test_colour_names_people_use(rgb, name):
    assert colour_name(rgb) == name


def test_shading_aware_naming_keeps_white_white_in_shade_and_grey_grey():
    table = colour_table()

    def named(rgb, shading=DECLARED_SHADING):
        return table.names[int(name_lab(rgb_to_lab(np.array(rgb, np.float64)), shading))]

    assert named((230, 230, 230), shading=None) == "light grey"  # the plain nearest name
    assert named((230, 230, 230)) == "white"  # white in shade: pixels are never brighter than the surface
    assert named((0xD8, 0xDC, 0xD6)) == "light grey"  # a grey that fits as it is stays grey
    assert named((0x92, 0x95, 0x91)) == "grey"
    assert named((0xE6 * 0.9, 0xDA * 0.9, 0xA6 * 0.9)) == "beige"
    # measured under room lighting, a darker view may still be white; a mid grey stays grey
    assert named((170, 170, 170)) != "white" and named((170, 170, 170), OBSERVED_SHADING) == "white"
    assert named((0x60, 0x60, 0x60), OBSERVED_SHADING) != "white"


def test_masked_lab_ignores_unmasked_pixels_and_shadowed_faces():
    navy = np.array([0x01, 0x15, 0x3E], np.float64)
    img = np.zeros((40, 40, 3), np.uint8)
    img[:] = (250, 20, 20)  # red background, outside the mask
    mask = np.zeros((40, 40), bool)
    mask[5:35, 5:35] = True
    img[5:35, 5:20] = np.round(navy * 1.0)           # lit face
    img[5:35, 20:35] = np.round(navy * 0.45)         # shadowed face (Lambert)
    lab, used = masked_lab(img, mask)
    assert 0 < used <= mask.sum()
    assert colour_table().names[int(name_lab(lab))] == "navy"
    assert ciede2000(lab, rgb_to_lab(navy)) < 3.0
    assert masked_lab(img, np.zeros((40, 40), bool)) is None
    with pytest.raises(ValueError):
        masked_lab(img, np.ones((10, 10), bool))


def _obs(rows):
    return np.array(rows, np.float64)


def test_keyframes_prefer_confident_steady_large_views():
    # instance 7: frames 0..9 observed (steady), frame 30 is a lone glimpse with a top score
    rows = [[7, f, 0, 400.0, 0.8] for f in range(10)] + [[7, 30, 1, 400.0, 0.99]]
    rows[5][3] = 800.0  # frame 5: largest view in the middle of the steady run
    rows.append([7, 5, 2, 100.0, 0.3])  # a split mask of the same instance in frame 5
    rows += [[9, 2, 1, 50.0, 0.5]]
    kfs = select_keyframes(_obs(rows), k=3)
    frames7 = [kf.frame for kf in kfs[7]]
    assert frames7[0] == 5 and 30 not in frames7 and len(frames7) == 3
    assert kfs[7][0].masks == (0, 2) and kfs[7][0].area == 900.0
    assert [kf.frame for kf in kfs[9]] == [2]
    scores = [kf.score for kf in kfs[7]]
    assert scores == sorted(scores, reverse=True)
    assert select_keyframes(_obs(rows), k=1)[7][0].frame == 5


def test_keyframes_reject_bad_input():
    assert select_keyframes(np.zeros((0, 5))) == {}
    with pytest.raises(IesmError):
        select_keyframes(np.zeros((3, 4)))
    with pytest.raises(IesmError):
        select_keyframes(_obs([[1, 0, 0, 10, 1]]), k=0)


def test_crop_box_grows_and_clips():
    mask = np.zeros((100, 100), bool)
    mask[40:60, 2:22] = True
    y0, y1, x0, x1 = crop_box(mask, margin=0.5, min_margin=4)
    assert (y0, y1, x0, x1) == (30, 70, 0, 32)
    assert crop_box(np.zeros((5, 5), bool)) is None


def test_outlined_png_is_a_png_of_the_crop_size():
    import cv2

    rgb = np.full((30, 50, 3), 200, np.uint8)
    mask = np.zeros((30, 50), bool)
    mask[10:20, 10:40] = True
    raw = base64.b64decode(outlined_png(rgb, mask))
    assert raw[:8] == b"\x89PNG\r\n\x1a\n"
    decoded = cv2.imdecode(np.frombuffer(raw, np.uint8), cv2.IMREAD_COLOR)
    assert decoded.shape == (30, 50, 3)
    assert (decoded[10, 20] == (0, 255, 0)).all() and (decoded[0, 0] == 200).all()


def test_caption_reply_cleans_tags_and_rejects_missing_caption():
    reply = CaptionReply.model_validate({"caption": "  a navy   sofa ", "tags": {
        "color": "Navy Blue.", "material": "null", "parts": "cushions, armrests", "extra": 1}})
    assert reply.caption == "a navy sofa"
    assert reply.tags.color == "navy blue" and reply.tags.material is None
    result = CaptionResult.from_reply(reply, {"size": "large"})
    assert result.tags == {"size": "large", "color": "navy blue", "parts": "cushions, armrests"}
    with pytest.raises(ValidationError):
        CaptionReply.model_validate({"tags": {}})
    with pytest.raises(ValidationError):
        CaptionReply.model_validate({"caption": ["a", "list"]})
    long = CaptionReply.model_validate({"caption": "word " * 200})
    assert len(long.caption) <= 300 and not long.caption.endswith(" ")
