"""Words the lexicon does not know are grounded in the map with the sentence encoder: an unknown
room phrase maps to the nearest room present, an unknown target phrase to the nearest label, and a
phrase near nothing (or near two options alike) grounds nothing."""

import json

import numpy as np

from iesm_agent.providers.base import Message
from iesm_agent.providers.offline import tasks
from iesm_agent.providers.offline.prompt import read_prompt
from iesm_agent.understanding import analyse_query, ground_query, stem

DIM = 8


def unit(*axes):
    v = np.zeros(DIM, np.float32)
    for a, w in axes:
        v[a] = w
    return v / np.linalg.norm(v)


class TableEncoder:
    """Fixed vectors per text (anything unlisted: a direction no listed text shares)."""

    name = "table-encoder"

    def __init__(self, table):
        self.table = table

    def encode(self, texts):
        return np.stack([self.table.get(t, unit((DIM - 1, 1.0))) for t in texts])


ENC = TableEncoder({
    "kitchen": unit((0, 1.0)), "bathroom": unit((1, 1.0)), "bedroom": unit((2, 1.0)),
    "scullery": unit((0, 1.0), (1, 0.3)),              # a kitchen, a little like a bathroom
    "wet room": unit((0, 0.5), (1, 0.52)),             # as near to kitchen as to bathroom: no call
    "sink": unit((3, 1.0)), "kettle": unit((4, 1.0)), "towel": unit((5, 1.0)),
    "gizmo": unit((4, 1.0), (3, 0.2)),                 # nearest the kettle
})
ROOMS, LABELS = ["kitchen", "bathroom", "bedroom"], ["sink", "kettle", "towel"]


def test_unknown_room_maps_to_the_nearest_room_in_the_map():
    q = analyse_query("the sink in the scullery")
    assert q.unknown_room == "scullery" and not q.rooms
    grounded = ground_query(q, ROOMS, LABELS, ENC)
    assert grounded.rooms == {"kitchen": 1.0} and grounded.room_phrase == "scullery"
    assert grounded.targets == q.targets  # the known target is left alone


def test_unknown_target_maps_to_the_nearest_label_in_the_map():
    q = analyse_query("the gizmo in the kitchen")
    assert q.unknown_target == "gizmo" and not q.targets
    grounded = ground_query(q, ROOMS, LABELS, ENC)
    assert set(grounded.targets) == {"kettle"} and grounded.rooms == q.rooms


def test_a_near_tie_or_a_far_phrase_grounds_nothing():
    tie = analyse_query("the towel in the wet room")
    assert ground_query(tie, ROOMS, LABELS, ENC).rooms == {}
    far = analyse_query("the thingamajig")  # the encoder puts it near no label
    assert ground_query(far, ROOMS, LABELS, ENC).targets == {}
    assert ground_query(tie, ROOMS, LABELS, None) is tie  # no encoder installed: as analysed


def _room_expert(query):
    lines = [json.dumps(c) for c in (
        {"id": 1, "label": "sink", "room": "bathroom"},
        {"id": 2, "label": "sink", "room": "kitchen"},
        {"id": 3, "label": "kettle", "room": "kitchen"},
        {"id": 4, "label": "towel", "room": "bathroom"},
    )]
    text = (f"Focus: <focus>Room location. Rank first by the room.</focus> Reply with "
            f"ranked_instance_ids, at most 2.\n<query>{json.dumps(query)}</query>\n"
            "<candidates>\n" + "\n".join(lines) + "\n</candidates>")
    return tasks.rank(read_prompt([Message(role="user", content=text)]), lambda: ENC)["ranked_instance_ids"]


def test_the_room_expert_ranks_by_the_grounded_room():
    assert _room_expert("the sink in the scullery")[0] == 2
    assert _room_expert("the gizmo in the bathroom")[:1] == [3]  # the only kettle, grounded by label


def test_a_misspelt_map_label_is_read_as_that_label_without_an_encoder():
    labels = ["flux capacitor", "kettle", "sofa"]
    q = analyse_query("take me to the flux capaciter")
    assert not q.named and stem("capacitor") not in q.overlap
    grounded = ground_query(q, ROOMS, labels, None)
    assert stem("capacitor") in grounded.overlap and grounded.target_phrase == q.unknown_target
    zorq = analyse_query("take me to the zorq")  # one edit from two labels: no call
    assert ground_query(zorq, ROOMS, ["zorb lamp", "zorf tray"], None) is zorq
    lines = [json.dumps({"id": i, "label": label}) for i, label in enumerate(labels, 1)]
    text = (f"Reply with ranked_instance_ids, at most 2.\n<query>{json.dumps('take me to the flux capaciter')}"
            "</query>\n<candidates>\n" + "\n".join(lines) + "\n</candidates>")
    assert tasks.rank(read_prompt([Message(role="user", content=text)]))["ranked_instance_ids"][:1] == [1]
