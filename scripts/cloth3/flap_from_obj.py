#!/usr/bin/env python3
"""test::flapMeasure (gallery/tear_measures.h) recomputed from `weft run --obj` frames: the torn
edges (the OBJ's `g torn` lines) in material space (the vt coordinates). Prints every STEP-th frame
(default 5) and the run's health. Usage: flap_from_obj.py RUN_DIR [STEP]"""
import sys, math, json, os
def load(path):
    vt=[]; vmap={}; lines=[]
    for ln in open(path):
        if ln.startswith('vt '): vt.append(tuple(map(float, ln.split()[1:3])))
        elif ln.startswith('f '):
            for c in ln.split()[1:]:
                a,b=c.split('/')[:2]; vmap[int(a)]=vt[int(b)-1]
        elif ln.startswith('l '):
            p=ln.split()[1:]; lines.append((int(p[0]),int(p[1])))
    segs=set()
    for a,b in lines:
        pa,pb=vmap[a],vmap[b]
        if (pb[0],pb[1])<(pa[0],pa[1]): pa,pb=pb,pa
        segs.add((round(pa[0],7),round(pa[1],7),round(pb[0],7),round(pb[1],7)))
    return [((s[0],s[1]),(s[2],s[3])) for s in segs]
def ang(s):
    d=math.degrees(math.atan2(s[1][1]-s[0][1], s[1][0]-s[0][0]))
    return d+180 if d<0 else d
def between(a,b):
    d=abs(a-b)%180; return min(d,180-d)
def L(s): return math.hypot(s[1][0]-s[0][0], s[1][1]-s[0][1])
def flap(segs, gap=0.04):
    vert=[s for s in segs if between(ang(s),90)<=22.5]
    mid=lambda s:0.5*(s[0][0]+s[1][0])
    vert.sort(key=mid); groups=[]
    for s in vert:
        x=mid(s)
        if not groups or x-groups[-1][1]>gap: groups.append([x,x,0.0])
        groups[-1][1]=x; groups[-1][2]+=L(s)
    out=dict(total=sum(map(L,segs)), vertical=sum(map(L,vert)), horizontal=sum(L(s) for s in segs if between(ang(s),0)<=22.5), left=0,right=0,sep=0,join=0, ngroups=len(groups))
    if len(groups)<2:
        if groups: out['left']=groups[0][2]
        return out
    g=sorted(groups,key=lambda g:-g[2])[:2]; g.sort(key=lambda g:g[0])
    out.update(left=g[0][2], right=g[1][2], sep=g[1][0]-g[0][1], gx=[(round(a,3),round(b,3)) for a,b,_ in g])
    out['join']=sum(L(s) for s in segs if between(ang(s),0)<=22.5 and g[0][1]<mid(s)<g[1][0])
    return out
if __name__=='__main__':
    d=sys.argv[1]
    frames=sorted(f for f in os.listdir(d+'/frames') if f.startswith('frame_'))
    m=json.load(open(d+'/metrics.json'))
    step=int(sys.argv[2]) if len(sys.argv)>2 else 5
    for f in frames[::step]+([frames[-1]] if (len(frames)-1)%step else []):
        r=flap(load(d+'/frames/'+f))
        print(f, ' '.join(f'{k}={v:.3f}' if isinstance(v,float) else f'{k}={v}' for k,v in r.items()))
    print('healthy',m['healthy'],'max_strain',round(m['max_strain'],2),'sim_time',m['sim_time_s'],'tears',m['tears'])
