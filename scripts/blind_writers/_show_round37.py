#!/usr/bin/env python3
"""Print a map compactly. Usage: show.py PATH"""
import json, sys
p = sys.argv[1]
d = json.load(open(p))
if 'objects' in d:
    for r in d.get('rooms', []):
        print('ROOM', r.get('id'), r.get('label'), r.get('polygon'))
    for o in d['objects']:
        c = o['center']; s = o['size']
        print(f"{o['id']:>3} {o['label']:<18} {str(o.get('room',''))[:14]:<14} c=({c[0]:.2f},{c[1]:.2f},{c[2]:.2f}) s=({s[0]:.2f},{s[1]:.2f},{s[2]:.2f}) {json.dumps(o.get('tags',{}))} | {o.get('caption','')}")
else:
    for k, v in d.items():
        try:
            cap = json.loads(v['caption'])
            txt = cap.get('captions', '') ; col = cap.get('color',''); mat = cap.get('material','')
        except Exception:
            txt = v['caption']; col = mat = ''
        print(f"{k:>4} {str(v['category']):<16} {str(v['room_cat']):<12} r{v['room_id']} [{col}/{mat}] {txt}")
