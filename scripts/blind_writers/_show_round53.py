import json, sys
from pathlib import Path
MAPS = {
 'flat_c': str(Path(__file__).resolve().parents[2] / 'evals/blind/maps/flat_c.json'),
 'flat_d': str(Path(__file__).resolve().parents[2] / 'evals/blind/maps/flat_d.json'),
 'flat_f': str(Path(__file__).resolve().parents[2] / 'evals/blind/maps/flat_f.json'),
 'flat_h': str(Path(__file__).resolve().parents[2] / 'evals/blind/maps/flat_h.json'),
 'apartment': str(Path(__file__).resolve().parents[2] / 'map_store/apartment.json'),
 'scan_bedroom': str(Path(__file__).resolve().parents[2] / 'evals/maps/scan_bedroom.json'),
 'scan_kitchen': str(Path(__file__).resolve().parents[2] / 'evals/maps/scan_kitchen.json'),
 'scan_livingroom': str(Path(__file__).resolve().parents[2] / 'evals/maps/scan_livingroom.json'),
 'scan_office': str(Path(__file__).resolve().parents[2] / 'evals/maps/scan_office.json'),
 'scene_00829': str(Path(__file__).resolve().parents[3] / 'shared/data/iesm_maps/scene_00829_caption.json'),
 'scene_office3': str(Path(__file__).resolve().parents[3] / 'shared/data/iesm_maps/scene_office3_caption.json'),
}
name = sys.argv[1]
d = json.load(open(MAPS[name]))
if isinstance(d, dict) and 'objects' in d:
    print({k: v for k, v in d.items() if k != 'objects'})
    for o in d['objects']:
        c = [round(x, 2) for x in o.get('center', [])]; s = [round(x, 2) for x in o.get('size', [])]
        extra = {k: v for k, v in o.items() if k not in ('id','label','center','size','room','tags','caption')}
        print(f"{o['id']:>3} {o['label']:<18} {o.get('room','')!s:<12} c={c} s={s} tags={o.get('tags')} {extra or ''}\n      {o.get('caption','')}")
else:
    for k, v in d.items():
        print(k, json.dumps(v)[:2000])
