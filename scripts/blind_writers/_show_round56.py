import json
import sys
from pathlib import Path
B = str(Path(__file__).resolve().parents[2]) + "/"
P = {
 'flat_b': B + 'evals/blind/maps/flat_b.json',
 'flat_e': B + 'evals/blind/maps/flat_e.json',
 'flat_g': B + 'evals/blind/maps/flat_g.json',
 'flat_i': B + 'evals/blind/maps/flat_i.json',
 'apartment': B + 'map_store/apartment.json',
 'scan_bedroom': B + 'evals/maps/scan_bedroom.json',
 'scan_kitchen': B + 'evals/maps/scan_kitchen.json',
 'scan_livingroom': B + 'evals/maps/scan_livingroom.json',
 'scan_office': B + 'evals/maps/scan_office.json',
 '00829': B + '../shared/data/iesm_maps/scene_00829_caption.json',
 'office3': B + '../shared/data/iesm_maps/scene_office3_caption.json',
}
def show(name):
    d = json.load(open(P[name]))
    if isinstance(d, dict) and 'objects' in d:
        print('==', name, d.get('comment',''))
        for r in d.get('rooms', []):
            print('  ROOM', r)
        for o in d['objects']:
            c = [round(v,2) for v in o['center']]
            s=[round(v,2) for v in o['size']]
            extra = {k:v for k,v in o.items() if k not in ('id','label','center','size','room','tags','caption')}
            print(f"{o['id']:3} {o['label']:<18} {o.get('room',''):<12} c={c} s={s} {o.get('tags',{})} {extra if extra else ''}")
            if o.get('caption'):
                print('      ', o['caption'])
    else:
        print('==', name)
        for k, v in d.items():
            try:
                cap = json.loads(v['caption'])
            except Exception:
                cap = {'raw': v['caption']}
            print(f"{k:>4} {v['category']:<20} {v.get('room_cat','')}({v.get('room_id')}) col={cap.get('color')} mat={cap.get('material')}")
            print('        ', cap.get('captions', cap.get('raw')))
            ex = {kk:vv for kk,vv in v.items() if kk not in ('category','room_cat','room_id','category_idx','top5_categories','caption')}
            if ex:
                print('        EXTRA', ex)
for n in sys.argv[1:]:
    show(n)
