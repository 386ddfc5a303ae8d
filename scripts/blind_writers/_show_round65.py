"""Print a map compactly: python3 show.py PATH"""
import json
import sys
def load(path):
    d = json.load(open(path))
    if isinstance(d, dict) and 'objects' in d:
        return d, True
    return d, False
def cap_of(v):
    c = v.get('caption', '')
    try:
        j = json.loads(c)
        return j
    except Exception:
        return {'captions': c}
if __name__ == '__main__':
    d, geo = load(sys.argv[1])
    if geo:
        print(d['comment'])
        print('rooms:', json.dumps(d['rooms']))
        for o in d['objects']:
            print(o['id'], o['label'], o.get('alt_labels',''), o['room'], 'c=',o['center'], 's=',o['size'], o.get('tags',{}), '|', o.get('caption',''))
    else:
        for k, v in d.items():
            j = cap_of(v)
            print(k, v['category'], '|', v['room_cat'], v['room_id'], '|', j.get('color'), j.get('material'), '|', j.get('captions'), '| top5', v.get('top5_categories'))
