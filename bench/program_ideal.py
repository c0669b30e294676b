#!/usr/bin/env python3
"""The ideal time of an NC program (docs/PERFORMANCE.md, issue 36): the sum of
its motion blocks' lengths over min(F, 250 mm/s, config/xyz_machine.yaml's
v_max), G00 at 250 mm/s; arcs by I J or R in G17; no acceleration, dwell or
M function. A lower bound for bench/cam_programs.sh.
Usage: program_ideal.py PROGRAM.nc [..]"""
import math
import re
import sys


def ideal(path):
    pos=[0.0,0.0,0.0]; F=None; mode=0; t=0; L=0; inch=False; absolute=True
    for raw in open(path):
        l=raw.split(';')[0]; l=re.sub(r'\(.*?\)','',l).upper()
        if l.strip().startswith('#') or l.strip().startswith('%'): continue
        if re.search(r'\bG0*0\b',l): mode=0
        if re.search(r'\bG0*1\b',l): mode=1
        if re.search(r'\bG0*2\b',l): mode=2
        if re.search(r'\bG0*3\b',l): mode=3
        if re.search(r'\bG91\b',l): absolute=False
        if re.search(r'\bG90\b',l): absolute=True
        m=re.search(r'F([0-9.]+)',l)
        if m: F=float(m.group(1))/60
        new=pos[:]
        for a,i in (('X',0),('Y',1),('Z',2)):
            m=re.search(a+r'(-?[0-9.]+)',l)
            if m: new[i]=float(m.group(1)) if absolute else pos[i]+float(m.group(1))
        if new==pos: continue
        d=math.dist(new,pos)
        if mode in (2,3):
            # arc length from I J R if present (approx: chord * 1.0 unless I/J given)
            mi=re.search(r'I(-?[0-9.]+)',l); mj=re.search(r'J(-?[0-9.]+)',l); mr=re.search(r'R(-?[0-9.]+)',l)
            if mi or mj:
                cx=pos[0]+(float(mi.group(1)) if mi else 0); cy=pos[1]+(float(mj.group(1)) if mj else 0)
                r=math.hypot(pos[0]-cx,pos[1]-cy)
                a0=math.atan2(pos[1]-cy,pos[0]-cx); a1=math.atan2(new[1]-cy,new[0]-cx)
                sw=(a1-a0) if mode==3 else (a0-a1)
                while sw<=1e-12: sw+=2*math.pi
                d=r*sw
            elif mr:
                r=abs(float(mr.group(1))); c=math.hypot(new[0]-pos[0],new[1]-pos[1]); th=2*math.asin(min(1,c/(2*r)))
                if float(mr.group(1))<0: th=2*math.pi-th
                d=r*th
        v = 250 if mode==0 else min(F,250)
        t+=d/v; pos=new
    return t
for p in sys.argv[1:]:
    print(p, round(ideal(p), 3))
