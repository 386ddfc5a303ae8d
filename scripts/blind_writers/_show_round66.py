import json
import sys
from pathlib import Path
ROOT = Path(__file__).resolve().parents[2]
B = ROOT / 'evals' / 'blind'
MAPS = {
 'maps/flat_b.json': B/'maps/flat_b.json',
 'maps/flat_e.json': B/'maps/flat_e.json',
 'maps/flat_g.json': B/'maps/flat_g.json',
 'maps/flat_i.json': B/'maps/flat_i.json',
 'apartment': ROOT / 'map_store' / 'apartment.json',
 '../maps/scan_bedroom.json': B/'../maps/scan_bedroom.json',
 '../maps/scan_kitchen.json': B/'../maps/scan_kitchen.json',
 '../maps/scan_livingroom.json': B/'../maps/scan_livingroom.json',
 '../maps/scan_office.json': B/'../maps/scan_office.json',
 '../../../shared/data/iesm_maps/scene_00829_caption.json': B/'../../../shared/data/iesm_maps/scene_00829_caption.json',
 '../../../shared/data/iesm_maps/scene_office3_caption.json': B/'../../../shared/data/iesm_maps/scene_office3_caption.json',
}
def load(key):
    d = json.loads(MAPS[key].read_text())
    out = []
    if isinstance(d, dict) and 'objects' in d:
        for o in d['objects']:
            out.append(dict(id=o['id'], label=o['label'], room=o.get('room'), center=o.get('center'), size=o.get('size'),
                            tags=o.get('tags', {}), caption=o.get('caption', ''), alt=o.get('alt_labels', [])))
        return d, out, True
    for k, v in d.items():
        try:
            c = json.loads(v['caption'])
        except Exception:
            c = {'captions': v['caption']}
        out.append(dict(id=int(k), label=v['category'], room=v.get('room_cat'), room_id=v.get('room_id'), tags={'color': c.get('color'), 'material': c.get('material')},
                        caption=c.get('captions', ''), alt=v.get('top5_categories', [])))
    return d, out, False
if __name__ == '__main__':
    key = sys.argv[1]
    d, objs, geo = load(key)
    if geo:
        print(d.get('comment'))
        for r in d['rooms']:
            print('ROOM', r['id'], r['label'], r['polygon'])
    for o in objs:
        if geo:
            print(o['id'], o['label'], '|', o['room'], '|', o['center'], o['size'], '|', o['tags'], '|', o['alt'], '|', o['caption'])
        else:
            print(o['id'], o['label'], '|', o['room'], o.get('room_id'), '|', o['tags'], '|', o['caption'])
