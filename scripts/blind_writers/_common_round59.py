"""Shared helpers: map loading (paths as in the brief) and tokenisation."""
import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BLIND = ROOT / 'evals/blind'
MAPREL = {
    'flat_c': 'maps/flat_c.json', 'flat_d': 'maps/flat_d.json',
    'flat_f': 'maps/flat_f.json', 'flat_h': 'maps/flat_h.json',
    'apartment': 'apartment',
    'scan_bedroom': '../maps/scan_bedroom.json', 'scan_kitchen': '../maps/scan_kitchen.json',
    'scan_livingroom': '../maps/scan_livingroom.json', 'scan_office': '../maps/scan_office.json',
    '00829': '../../../shared/data/iesm_maps/scene_00829_caption.json',
    'office3': '../../../shared/data/iesm_maps/scene_office3_caption.json',
}


def map_path(rel):
    if rel == 'apartment':
        return ROOT / 'map_store/apartment.json'
    return (BLIND / rel).resolve()


def parse_caption(raw):
    """Caption dictionaries hold a JSON-ish string; a few have a trailing comma."""
    try:
        return json.loads(raw)
    except ValueError:
        return json.loads(re.sub(r',\s*}\s*$', '}', raw.strip()))


def load(rel):
    """list of dicts: id, label, room, text (caption + tags), center, size (None on caption maps)."""
    d = json.loads(map_path(rel).read_text())
    out = []
    if 'objects' in d:
        for o in d['objects']:
            tags = o.get('tags', {})
            text = ' '.join([o.get('caption', '')] + [str(v) for v in tags.values()] + o.get('alt_labels', []))
            out.append(dict(id=o['id'], label=o['label'], room=o.get('room'), text=text.lower(),
                            caption=o.get('caption', ''), center=o['center'], size=o['size']))
    else:
        for k, v in d.items():
            c = parse_caption(v['caption'])
            text = ' '.join(str(c.get(f, '')) for f in ('color', 'material', 'captions'))
            out.append(dict(id=int(k), label=v['category'], room=v['room_cat'], room_id=v['room_id'],
                            text=text.lower(), caption=c.get('captions', ''), center=None, size=None))
    return out


def words(s):
    return re.findall(r"[a-z0-9]+", s.lower())
