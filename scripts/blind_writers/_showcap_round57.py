import json
import re
import sys
d = json.load(open(sys.argv[1]))
print(len(d))
for k, v in d.items():
    c = v.get("caption", "")
    m = re.search(r'"captions"\s*:\s*"(.*?)"\s*,?\s*\n', c, re.S)
    col = re.search(r'"color"\s*:\s*"(.*?)"', c)
    mat = re.search(r'"material"\s*:\s*"(.*?)"', c)
    print(k, v.get("category"), "|", v.get("room_cat"), v.get("room_id"), "|", col.group(1) if col else None, "|", mat.group(1) if mat else None, "|", m.group(1) if m else repr(c))
