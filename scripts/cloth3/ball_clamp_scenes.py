#!/usr/bin/env python3
"""Fourteenth-session Cloth 3 scenes (docs/tearing.md, Thesis Cloth 3): the shipped scene
ball-into-sheet-table4.1-cloth3.json with its four corner clamps replaced by whole-edge clamps
(--top/--bot/--side: depth in rest units, 0 = none) and the ball changed (--by rest height,
--bx x offset, --r radius, --m mass, --v speed into the sheet, --down its path turned downward
in degrees). Writes the scene to --out; run it
with `weft run SCENE --obj --out DIR` and measure with flap_from_obj.py DIR."""
import json,sys,argparse,os,math
p=argparse.ArgumentParser()
p.add_argument('--res',type=int,default=40)
p.add_argument('--top',type=float,default=0.03)   # top clamp depth (rest y >= 1-top), 0 none
p.add_argument('--bot',type=float,default=0)      # bottom clamp depth
p.add_argument('--side',type=float,default=0)     # left/right clamp depth
p.add_argument('--by',type=float,default=0.5)     # ball rest height
p.add_argument('--bx',type=float,default=0.0)
p.add_argument('--r',type=float,default=0.08)
p.add_argument('--m',type=float,default=2.0)
p.add_argument('--v',type=float,default=12)
p.add_argument('--down',type=float,default=0)    # the ball's path turned this many degrees downward (same speed)
p.add_argument('--frames',type=int,default=45)
p.add_argument('--out')
a=p.parse_args()
s=json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)),'../../presets/scenes/ball-into-sheet-table4.1-cloth3.json')))
c=s['cloths'][0]; c['mesh']['grid']['resolution']=[a.res,a.res]
pins=[]
def box(x0,y0,x1,y1): pins.append({'rest_box':{'min':[x0,y0],'max':[x1,y1]}})
e=1e-4
if a.top>0: box(-e,1-a.top-e,1+e,1+e)
if a.bot>0: box(-e,-e,1+e,a.bot+e)
if a.side>0: box(-e,-e,a.side+e,1+e); box(1-a.side-e,-e,1+e,1+e)
c['pins']=pins
o=s['obstacles'][0]; o['shape']['sphere']['radius']=a.r
o['placement']['translate']=[a.bx,0.5+a.by,a.r+0.42]
o['motion']['dynamic']['mass']=a.m
o['motion']['dynamic']['velocity']=[0,-a.v*math.sin(math.radians(a.down)),-a.v*math.cos(math.radians(a.down))] if a.down else [0,0,-a.v]
s['output']['frames']=a.frames
json.dump(s,open(a.out,'w'),indent=1)
