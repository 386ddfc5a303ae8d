import json, sys
from pathlib import Path
B = Path(__file__).resolve().parents[2] / 'evals/blind'
MAPS = {
 'maps/flat_b.json': B/'maps/flat_b.json', 'maps/flat_e.json': B/'maps/flat_e.json',
 'maps/flat_g.json': B/'maps/flat_g.json', 'maps/flat_i.json': B/'maps/flat_i.json',
 'apartment': Path(__file__).resolve().parents[2] / 'map_store/apartment.json',
 '../maps/scan_bedroom.json': B/'../maps/scan_bedroom.json', '../maps/scan_kitchen.json': B/'../maps/scan_kitchen.json',
 '../maps/scan_livingroom.json': B/'../maps/scan_livingroom.json', '../maps/scan_office.json': B/'../maps/scan_office.json',
 '../../../shared/data/iesm_maps/scene_00829_caption.json': B/'../../../shared/data/iesm_maps/scene_00829_caption.json',
 '../../../shared/data/iesm_maps/scene_office3_caption.json': B/'../../../shared/data/iesm_maps/scene_office3_caption.json',
}
def load(name):
    d = json.loads(MAPS[name].read_text())
    if isinstance(d, dict) and 'objects' in d:
        return d, True
    return d, False
if __name__ == '__main__':
    for name in sys.argv[1:]:
        d, geo = load(name)
        if geo:
            print('##', name, d.get('comment',''))
            for r in d['rooms']: print('  room', r)
            for o in d['objects']:
                print(f"{o['id']:3d} {o['label']:<16} c={o['center']} s={o['size']} room={o.get('room')} tags={o.get('tags')} alt={o.get('alt_labels','')}\n      {o.get('caption','')}")
        else:
            print('##', name)
            for k, v in d.items():
                try: c = json.loads(v['caption'])
                except Exception: c = {'captions': v['caption']}
                print(f"{k:>4} {v['category']:<20} room={v.get('room_cat')}/{v.get('room_id')} col={c.get('color')} mat={c.get('material')}\n      {c.get('captions')}")
