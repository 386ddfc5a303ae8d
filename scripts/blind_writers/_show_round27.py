import json,sys
def cap(v):
    c=v['caption']
    try:
        d=json.loads(c); return f"[{d.get('color','')}|{d.get('material','')}] {d.get('captions','')}"
    except Exception: return c
for f in sys.argv[1:]:
    d=json.load(open(f))
    print('=====',f)
    if isinstance(d,dict) and 'objects' in d:
        print('rooms:',[(r['label'],r['polygon'] if len(r['polygon'])<=4 else r['polygon']) for r in d['rooms']])
        for o in d['objects']:
            c=o['center'];s=o['size']
            print(f"{o['id']:3} {o['label']:22} {o.get('room',''):14} c=({c[0]:.2f},{c[1]:.2f},{c[2]:.2f}) s=({s[0]:.2f},{s[1]:.2f},{s[2]:.2f}) alt={o.get('alt_labels','')} tags={o.get('tags','')} | {o.get('caption','')}")
    else:
        for k,v in d.items():
            print(f"{k:4} {v['category']:20} {v['room_cat']}({v['room_id']}) | {cap(v)}")
