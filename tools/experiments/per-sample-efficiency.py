#!/usr/bin/env python3
"""Per-sample variance and CPU time of two builds on the same scenes (an experiment's quick check,
not a benchmark): each build renders SCENE at 160x90, SPP samples, 1 thread, seed 3, the
independent sampler (so `--variance` is exact), timed by /usr/bin/time; prints the mean stated
variance of a pixel's mean, the user CPU seconds, and their ratios, new over old.
Usage: /usr/bin/python3 tools/experiments/per-sample-efficiency.py OLD,NEW SCENE[,SCENE...] [SPP]
(scenes: cornell-box, smallpt, kitchen, staircase2, coffee, classroom; renders go to /tmp/lead)."""
import sys, subprocess, os, numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
from equal_time import read_pfm
REPO = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
S = os.path.join(REPO, '..', 'shared', 'bitterli')
scenes={'cornell-box':REPO + '/scenes/cornell-box.json','kitchen':S+'/kitchen/scene-v4.pbrt','staircase2':S+'/staircase2/scene-v4.pbrt','coffee':S+'/coffee/scene-v4.pbrt','smallpt':REPO + '/scenes/smallpt.json','classroom':S+'/classroom/scene-v4.pbrt'}
bins=sys.argv[1].split(',')
names=sys.argv[2].split(',')
spp=sys.argv[3] if len(sys.argv)>3 else '64'
for n in names:
    row=[]
    for b in bins:
        os.makedirs('/tmp/lead', exist_ok=True)
        out=f'/tmp/lead/pv-{n}-{os.path.basename(b)}'
        cmd=[b,'render',scenes[n],'--width','160','--height','90','--spp',spp,'--threads','1','--seed','3','--sampler','independent','-o',out+'.pfm','--variance',out+'-var.pfm']
        r=subprocess.run(['/usr/bin/time','-f','%U']+cmd,stderr=subprocess.PIPE,text=True)
        cpu=float(r.stderr.strip().split('\n')[-1])
        v=read_pfm(out+'-var.pfm'); ok=np.isfinite(v)
        row.append((np.mean(v[ok]), cpu))
    base=row[0]
    print(n, ' '.join(f'{os.path.basename(b)}: var {v:.4g} cpu {c:.2f}s' for b,(v,c) in zip(bins,row)),
          '| var ratio %.3f, cpu ratio %.3f, efficiency gain (var*cpu) %.3f' % (row[1][0]/base[0], row[1][1]/base[1], base[0]*base[1]/(row[1][0]*row[1][1])), flush=True)
