import json
import sys
p = sys.argv[1]
d = json.load(open(p))
if isinstance(d, dict) and "objects" in d:
    print({k: (v if k != "objects" else len(v)) for k, v in d.items()})
    for o in d["objects"]:
        print(json.dumps(o))
else:
    for k, v in d.items():
        print(k, json.dumps(v))
