#!/usr/bin/env python3
# Time to image, before against after, alternated in one run (docs/measurements.md#time-to-image-44-2026-11-30):
#   tools/time-to-image.py BEFORE_CANDELA AFTER_CANDELA SAMPLES_MODELS_FOLDER [OUT.json]
# Single renders (three fresh processes each, after one that warms the caches), bench frame ratios
# (two rounds) and the whole samples folder at 512 x 512 in one run (two rounds); the calibration
# pass of the after binary at the start, middle and end. Prints as it goes; writes OUT.json.
import subprocess, time, re, json, sys
if len(sys.argv) < 4:
    sys.exit('usage: time-to-image.py BEFORE_CANDELA AFTER_CANDELA SAMPLES_MODELS_FOLDER [OUT.json]')
B, A, S = sys.argv[1], sys.argv[2], sys.argv[3].rstrip('/')
OUT = sys.argv[4] if len(sys.argv) > 4 else 'time-to-image.json'
H = S + '/DamagedHelmet/glTF-Binary/DamagedHelmet.glb'
M = S + '/MetalRoughSpheresNoTextures/glTF-Binary/MetalRoughSpheresNoTextures.glb'
out = {}
def wall(cmd):
    t = time.perf_counter(); r = subprocess.run(cmd, capture_output=True, text=True); dt = time.perf_counter() - t
    if r.returncode: print('FAILED', cmd, r.stderr[:300], flush=True)
    return dt * 1000
def calib():
    r = subprocess.run([A, 'bench', '--frames', '3'], capture_output=True, text=True).stdout
    return float(re.search(r'calibration: median ([0-9.]+) ms', r).group(1))
def bench(binary, args):
    r = subprocess.run([binary, 'bench', '--frames', '20'] + args, capture_output=True, text=True).stdout
    f = re.search(r'^  frame: .*?; ([0-9.]+)x calibration', r, re.M).group(1)
    return float(f)
cal = [calib()]
# single renders, process start to file: warm run first
for name, args in [('helmet 1280x720', ['--scene', H]), ('default 1280x720', []), ('MRSNT 512', ['--scene', M, '--width', '512', '--height', '512'])]:
    res = {'before': [], 'after': []}
    for b in (B, A): wall([b, 'render', '--out', 'time-to-image.png', '--quiet'] + args)  # warm caches
    for i in range(3):
        for label, b in (('before', B), ('after', A)):
            res[label].append(wall([b, 'render', '--out', 'time-to-image.png', '--quiet'] + args))
    out[name] = res; print(name, {k: [round(v) for v in vs] for k, vs in res.items()}, flush=True)
cal.append(calib())
# frames
for name, args in [('grid frame 1280x720', []), ('helmet frame 1280x720', ['--scene', H]), ('helmet frame 640x360', ['--scene', H, '--width', '640', '--height', '360'])]:
    res = {'before': [], 'after': []}
    for i in range(2):
        for label, b in (('before', B), ('after', A)):
            res[label].append(bench(b, args))
    out[name] = res; print(name, res, flush=True)
# batch of 85
res = {'before': [], 'after': []}
for i in range(2):
    for label, b in (('before', B), ('after', A)):
        rep = f'time-to-image-batch-{label}-{i}.json'
        ms = wall([b, 'render', S + '/', '--out', f'time-to-image-{label}/{{path}}.png', '--width', '512', '--height', '512', '--quiet', '--report', rep])
        res[label].append(ms)
out['85 files 512'] = res; print('85 files', {k: [round(v) for v in vs] for k, vs in res.items()}, flush=True)
cal.append(calib())
out['calibration'] = cal
print('calibration', cal)
json.dump(out, open(OUT, 'w'), indent=1)
