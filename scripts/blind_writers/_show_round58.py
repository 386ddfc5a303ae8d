import json
import sys
from pathlib import Path

B = str(Path(__file__).resolve().parents[2]) + '/'
OBJ = {'flat_b': B + 'evals/blind/maps/flat_b.json', 'flat_e': B + 'evals/blind/maps/flat_e.json',
       'flat_g': B + 'evals/blind/maps/flat_g.json', 'flat_i': B + 'evals/blind/maps/flat_i.json',
       'apartment': B + 'map_store/apartment.json', 'scan_bedroom': B + 'evals/maps/scan_bedroom.json',
       'scan_kitchen': B + 'evals/maps/scan_kitchen.json', 'scan_livingroom': B + 'evals/maps/scan_livingroom.json',
       'scan_office': B + 'evals/maps/scan_office.json'}
CAP = {'scene_00829': B + '../shared/data/iesm_maps/scene_00829_caption.json',
       'scene_office3': B + '../shared/data/iesm_maps/scene_office3_caption.json'}


def show(name):
    if name in OBJ:
        d = json.load(open(OBJ[name]))
        print('##', name, d.get('comment'))
        for r in d['rooms']:
            print('  room', r)
        for o in d['objects']:
            extra = {k: v for k, v in o.items() if k not in ('id', 'label', 'center', 'size', 'room', 'tags', 'caption')}
            print(o['id'], o['label'], o['center'], o['size'], o.get('room'), o.get('tags'), extra or '', '|',
                  o.get('caption', ''))
    else:
        d = json.load(open(CAP[name]))
        print('##', name, len(d))
        for k, v in d.items():
            try:
                c = json.loads(v['caption'])
            except Exception:
                c = {'captions': v['caption']}
            print(k, v['category'], '|', v.get('room_cat'), v.get('room_id'), '|', c.get('color'), '|',
                  c.get('material'), '|', c.get('captions'))


for n in sys.argv[1:]:
    show(n)
