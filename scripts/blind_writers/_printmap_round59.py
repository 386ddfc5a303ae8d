import json
import sys
from pathlib import Path

B = str(Path(__file__).resolve().parents[2]) + '/'
MAPS = {
    'flat_c': B + 'evals/blind/maps/flat_c.json',
    'flat_d': B + 'evals/blind/maps/flat_d.json',
    'flat_f': B + 'evals/blind/maps/flat_f.json',
    'flat_h': B + 'evals/blind/maps/flat_h.json',
    'apartment': B + 'map_store/apartment.json',
    'scan_bedroom': B + 'evals/maps/scan_bedroom.json',
    'scan_kitchen': B + 'evals/maps/scan_kitchen.json',
    'scan_livingroom': B + 'evals/maps/scan_livingroom.json',
    'scan_office': B + 'evals/maps/scan_office.json',
    '00829': B + '../shared/data/iesm_maps/scene_00829_caption.json',
    'office3': B + '../shared/data/iesm_maps/scene_office3_caption.json',
}
name = sys.argv[1]
d = json.load(open(MAPS[name]))
if 'objects' in d:
    print(d.get('comment'))
    for r in d['rooms']:
        print('ROOM', r['id'], r['label'], r.get('polygon'))
    for o in d['objects']:
        extra = {k: v for k, v in o.items() if k not in ('id', 'label', 'center', 'size', 'room')}
        print(o['id'], o['label'], '|', o.get('room'), '| c', o['center'], 's', o['size'], '|', json.dumps(extra))
else:
    for k, v in d.items():
        try:
            c = json.loads(v['caption'])
        except Exception:
            c = v['caption']
        if isinstance(c, dict):
            print(k, v['category'], '|', v['room_cat'], v['room_id'], '|', c.get('color'), '|', c.get('material'), '|',
                  c.get('captions'))
        else:
            print(k, v['category'], '|', v['room_cat'], v['room_id'], '| RAW', c)
