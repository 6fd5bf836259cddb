#!/usr/bin/env python3
"""Scenes of the ninth session's Cloth 3 attempts (docs/tearing.md, "Thesis Cloth 3", ninth session).

A 1 m royal-target sheet (40^2, Cloth 3's tear table, world x = u - 0.5, y = v + 0.5, z = 0; clamps
--clamp: tb10 = top and bottom edges 0.1 m deep, tb6, tb3, all10 = those and the sides, corners)
is struck by two kinematic spheres (radius --sr, at x = +-xs, y = --sy, at --sv m/s along -z), which
open two vertical tears by 0.35 s. Then, by --tool:
  rod    a capsule along z (radius --tr, half length --thl) enters the left tear from the front
         (--tin to --tdrag) and is dragged along +x (--dir -1: the right tear, along -x) at height
         --ty, plane offset --tz, --tv m/s over --dist m (--rodx: start x; --inplane --nospheres:
         no spheres, the rod starts in the sheet's plane, e.g. outside its free left border)
  sphere the left sphere comes back into the plane and is dragged the same way
  vcap   a capsule along y enters the left tear and is dragged the same way
  hcap   a capsule along x, across the strip, is pushed through the sheet (-z) at height --ty
--squeeze D: rods in both tears move D toward each other (over --sqt s from --tdrag);
--stretch D: the top and bottom clamps (pieces x in [--piece, 1 - piece], or all with --piece 0)
move D apart; --pull D: the bottom clamp's piece under the strip moves D down.
Run: python3 scripts/cloth3/cloth3_scenes.py --out /tmp/s.json ARGS;
     weft run /tmp/s.json --out DIR --obj --keep-going; python3 scripts/cloth3/flap_from_obj.py DIR"""
import json, sys, argparse
p=argparse.ArgumentParser()
p.add_argument('--out'); p.add_argument('--res',type=int,default=40)
p.add_argument('--clamp',default='tb10')  # tb3, tb10, all10, corners
p.add_argument('--xs',type=float,default=0.2)   # sphere x = +-xs
p.add_argument('--sr',type=float,default=0.10)  # sphere radius
p.add_argument('--sv',type=float,default=1.0)   # sphere speed
p.add_argument('--sy',type=float,default=1.0)   # sphere world y
p.add_argument('--tool',default='rod')  # rod | sphere | vcap | none
p.add_argument('--tr',type=float,default=0.02)  # tool radius
p.add_argument('--thl',type=float,default=0.3)  # tool half length
p.add_argument('--ty',type=float,default=1.0)   # tool world y (rest v = y-0.5)
p.add_argument('--tz',type=float,default=0.0)   # plane offset of the drag
p.add_argument('--tv',type=float,default=1.0)   # drag speed
p.add_argument('--tin',type=float,default=0.6)  # time the tool starts entering
p.add_argument('--tdrag',type=float,default=0.9)  # time the drag starts
p.add_argument('--dir',type=float,default=1.0)
p.add_argument('--rodx',type=float,default=None)
p.add_argument('--nospheres',action='store_true')
p.add_argument('--inplane',action='store_true')
p.add_argument('--squeeze',type=float,default=0.0)  # each rod moves this far toward the middle
p.add_argument('--stretch',type=float,default=0.0)  # strip clamp pieces move apart by this each
p.add_argument('--sqt',type=float,default=0.4)      # duration of squeeze/stretch
p.add_argument('--stretch_start',type=float,default=None)
p.add_argument('--piece',type=float,default=0.3)
p.add_argument('--pull',type=float,default=0.0)  # strip's bottom clamp piece moves down this far
p.add_argument('--pullz',type=float,default=0.0)    # strip clamp pieces: rest x in [piece, 1-piece]
p.add_argument('--sdelay',type=float,default=0.0)  # +1: from left tear to right
p.add_argument('--dist',type=float,default=None)  # drag distance (default 2*xs+0.1)
p.add_argument('--fr',type=float,default=0.3)
p.add_argument('--sfr',type=float,default=1.0)
p.add_argument('--end',type=float,default=None)
p.add_argument('--grav',type=float,default=-9.81)
a=p.parse_args()
def box(x0,y0,x1,y1): return {"rest_box":{"min":[x0,y0],"max":[x1,y1]}}
if a.clamp=='tb3': pins=[box(0,0,1,0.03),box(0,0.97,1,1)]
elif a.clamp=='tb10': pins=[box(0,0,1,0.1),box(0,0.9,1,1)]
elif a.clamp=='tb6': pins=[box(0,0,1,0.06),box(0,0.94,1,1)]
elif a.clamp=='all10': pins=[box(0,0,1,0.1),box(0,0.9,1,1),box(0,0,0.03,1),box(0.97,0,1,1)]
elif a.clamp=='corners': pins=[box(0,0,0.06,0.06),box(0.94,0,1,0.06),box(0,0.94,0.06,1),box(0.94,0.94,1,1)]
else: raise SystemExit('clamp?')
obst=[]
zs=a.sr+0.05; zend=-(a.sr+0.35); tend=(zs-zend)/a.sv
for name,x in (('left',-a.xs),('right',a.xs)):
    obst.append({"name":name,"shape":{"sphere":{"radius":a.sr,"subdivisions":3}},
      "motion":{"kinematic":{"keyframes":[{"t":a.sdelay,"translate":[x,a.sy,zs],"rotate_deg":[0,0,0]},
                                           {"t":a.sdelay+tend,"translate":[x,a.sy,zend],"rotate_deg":[0,0,0]}]}},"friction":a.sfr})
dist=a.dist if a.dist is not None else 2*a.xs+0.1
x0=-a.xs*a.dir if a.rodx is None else a.rodx; x1=x0+a.dir*dist
tdrag_end=a.tdrag+dist/a.tv
if a.tool=='hcap': tdrag_end=a.tin+dist/a.tv
if a.tool=='rod':
    # capsule along z: enters the tear from the front, then is dragged in the plane
    zc0=a.thl+a.tr+0.1
    shape={"capsule":{"radius":a.tr,"half_length":a.thl,"segments":24}}; rot=[90,0,0]
    keys=[{"t":0,"translate":[x0,a.ty,zc0],"rotate_deg":rot},{"t":a.tin,"translate":[x0,a.ty,zc0],"rotate_deg":rot},
          {"t":a.tdrag,"translate":[x0,a.ty,a.tz],"rotate_deg":rot},{"t":tdrag_end,"translate":[x1,a.ty,a.tz],"rotate_deg":rot}]
    if a.inplane: keys=[{"t":0,"translate":[x0,a.ty,a.tz],"rotate_deg":rot},{"t":a.tdrag,"translate":[x0,a.ty,a.tz],"rotate_deg":rot},{"t":tdrag_end,"translate":[x1,a.ty,a.tz],"rotate_deg":rot}]
    obst.append({"name":"tool","shape":shape,"motion":{"kinematic":{"keyframes":keys}},"friction":a.fr})
elif a.tool=='hcap':
    # capsule along x across the strip, pushed through the sheet (-z) at height ty
    rot=[0,0,90]; zc0=a.tr+0.1
    keys=[{"t":0,"translate":[0,a.ty,zc0],"rotate_deg":rot},{"t":a.tin,"translate":[0,a.ty,zc0],"rotate_deg":rot},
          {"t":a.tin+a.dist/a.tv,"translate":[0,a.ty,zc0-a.dist],"rotate_deg":rot}]
    tdrag_end=a.tin+a.dist/a.tv
    obst.append({"name":"tool","shape":{"capsule":{"radius":a.tr,"half_length":a.thl,"segments":24}},"motion":{"kinematic":{"keyframes":keys}},"friction":a.fr})
elif a.tool=='vcap':
    # capsule along y lying in the plane inside the left tear (enters from the front)
    zc0=a.tr+0.15
    shape={"capsule":{"radius":a.tr,"half_length":a.thl,"segments":24}}; rot=[0,0,0]
    keys=[{"t":0,"translate":[x0,a.ty,zc0],"rotate_deg":rot},{"t":a.tin,"translate":[x0,a.ty,zc0],"rotate_deg":rot},
          {"t":a.tdrag,"translate":[x0,a.ty,a.tz],"rotate_deg":rot},{"t":tdrag_end,"translate":[x1,a.ty,a.tz],"rotate_deg":rot}]
    obst.append({"name":"tool","shape":shape,"motion":{"kinematic":{"keyframes":keys}},"friction":a.fr})
elif a.tool=='sphere':
    # the left sphere itself comes back into the plane, then is dragged
    k=obst[0 if a.dir>0 else 1]["motion"]["kinematic"]["keyframes"]
    k.append({"t":a.tin,"translate":[x0,a.sy,zend],"rotate_deg":[0,0,0]})
    k.append({"t":a.tdrag,"translate":[x0,a.ty,a.tz],"rotate_deg":[0,0,0]})
    k.append({"t":tdrag_end,"translate":[x1,a.ty,a.tz],"rotate_deg":[0,0,0]})
if a.nospheres: obst=[o for o in obst if o['name']=='tool']
if a.squeeze>0 or a.stretch>0:
    obst=[o for o in obst if o['name']!='tool']
    rot=[90,0,0]; zc0=a.thl+a.tr+0.1
    for name,x,sg in (('rodL',-a.xs,1),('rodR',a.xs,-1)):
        keys=[{"t":0,"translate":[x,a.ty,zc0],"rotate_deg":rot},{"t":a.tin,"translate":[x,a.ty,zc0],"rotate_deg":rot},
              {"t":a.tdrag,"translate":[x,a.ty,a.tz],"rotate_deg":rot},{"t":a.tdrag+a.sqt,"translate":[x+sg*a.squeeze,a.ty,a.tz],"rotate_deg":rot}]
        obst.append({"name":name,"shape":{"capsule":{"radius":a.tr,"half_length":a.thl,"segments":24}},"motion":{"kinematic":{"keyframes":keys}},"friction":a.fr})
    if a.stretch>0:
        c=0.1 if a.clamp=='tb10' else 0.03
        q=a.piece; ts=a.stretch_start if a.stretch_start is not None else a.tdrag
        pins=[box(0,0,q,c),box(1-q,0,1,c),box(0,1-c,q,1),box(1-q,1-c,1,1)] if q>0 else []
        for y0,y1,sg in ((0,c,-1),(1-c,1,1)):
            b=box(q,y0,1-q,y1); b["script"]=[{"t":ts,"offset":[0,0,0]},{"t":ts+a.sqt,"offset":[0,sg*a.stretch,0]}]
            pins.append(b)
    tdrag_end=a.tdrag+a.sqt
if a.pull>0:
    obst=[o for o in obst if o['name']!='tool']
    c=0.1 if a.clamp=='tb10' else (0.06 if a.clamp=='tb6' else 0.03); q=a.piece
    b=box(q,0,1-q,c); b["script"]=[{"t":a.tdrag,"offset":[0,0,0]},{"t":a.tdrag+a.sqt,"offset":[0,-a.pull,a.pullz]}]
    pins=[box(0,1-c,1,1),box(0,0,q,c),box(1-q,0,1,c),b]
    tdrag_end=a.tdrag+a.sqt
end=a.end if a.end else tdrag_end+0.1
fps=60
sc={"name":"ball-dragged-through-sheet-table4.1-cloth3","description":"generated",
 "cloths":[{"name":"sheet","mesh":{"grid":{"width":1.0,"height":1.0,"resolution":[a.res,a.res]}},
   "placement":{"translate":[-0.5,0.5,0.0]},"material":"royal-target","tear_table":"karaoz2015-table4.1-cloth3",
   "weft_angle_deg":0,"appearance":{"color":[0.85,0.66,0.22]},"pins":pins}],
 "obstacles":obst,"contact":{"thickness":0.004},
 "forces":{"gravity":[0,a.grav,0],"damping":{"mass":0.05}},
 "solver":{"dt":1/240},"output":{"frames":int(round(end*fps)),"fps":fps}}
json.dump(sc,open(a.out,'w'),indent=1)
