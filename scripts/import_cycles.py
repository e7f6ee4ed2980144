#!/usr/bin/env python3
"""Reports import cycles between the modules of a Rust source folder and exits 1 if any.

    python3 scripts/import_cycles.py src          # the whole crate
    python3 scripts/import_cycles.py src/trace    # one folder

A module depends on each module it names in a `use` line or an inline path (`crate::`,
`super::`, `self::`), and a folder's face (its mod.rs) on the children it declares. Test
modules and comments are left out. Cycles are the strongly connected components of that
graph with more than one module.

A top folder's face (`src/scene/mod.rs`) is the crate's door into that folder: its own
modules naming an item through it (`crate::scene::Scene`) are not counted, exactly as when
the folder is checked alone. Every other face, and every module between folders, counts.

Cycles in ALLOWED are reported but do not fail the check; each says why it may stay.
"""
import re,sys,os,glob

# Cycles that may stay, by full module path, each with its reason.
ALLOWED = {
    frozenset({'scene::model', 'scene::shape'}):
        'the scene model is a recursive type: an Object holds a Shape, and a CSG or group '
        'Shape holds Objects',
}

root=sys.argv[1].rstrip('/')
inner=root.split('src',1)[1].strip('/')
crate_prefix='crate'+('::'+inner.replace('/','::') if inner else '')
full_prefix=(inner.replace('/','::')+'::') if inner else ''
mods={}
for f in glob.glob(root+'/**/*.rs',recursive=True):
    rel=f[len(root)+1:-3]
    parts=rel.split('/')
    if parts[-1]=='mod': parts=parts[:-1]
    mods['::'.join(parts)]=f
def resolve(cur, path):
    segs=path.split('::')
    if segs[0]=='crate':
        pre=crate_prefix.split('::')
        if segs[:len(pre)]!=pre: return None
        segs=segs[len(pre):]; base=[]
    else:
        base=cur.split('::') if cur else []
        while segs and segs[0] in ('super','self'):
            if segs[0]=='super': base=base[:-1]
            segs=segs[1:]
    full=base+segs
    # longest prefix that is a module
    for k in range(len(full),0,-1):
        m='::'.join(full[:k])
        if m in mods: return m
    return None
def through_top_face(m, t):
    """Whether `m` names an item through the face of the top folder it lies in."""
    return not inner and '::' not in t and mods[t].endswith('mod.rs') and m.startswith(t+'::')
edges={}
for m,f in mods.items():
    src=open(f).read().split('#[cfg(test)]')[0]
    src=re.sub(r'//.*','',src)
    for u in re.finditer(r'\buse\s+((?:crate|super|self)::[^;]*);',src,re.S):
        body=u.group(1)
        # expand braces roughly
        def exp(prefix,tree):
            tree=tree.strip()
            mm=re.match(r'([A-Za-z_0-9:]+?)::\{(.*)\}$',tree,re.S)
            if mm:
                inner=mm.group(2);depth=0;cur='';out=[]
                for ch in inner:
                    if ch=='{':depth+=1
                    if ch=='}':depth-=1
                    if ch==',' and depth==0: out+=exp(prefix+mm.group(1)+'::',cur);cur=''
                    else: cur+=ch
                if cur.strip(): out+=exp(prefix+mm.group(1)+'::',cur)
                return out
            return [prefix+tree.split(' as ')[0].strip()]
        for p in exp('',body):
            p=re.sub(r'::self$','',p)
            t=resolve(m,p)
            if t is not None and t!=m and t!='' and not through_top_face(m,t):
                # a child using its own ancestor folder face counts as an edge to that face
                edges.setdefault(m,set()).add(t)
    for u in re.finditer(r'(?<![\w:])((?:crate|super)::[A-Za-z_0-9:]+)',src):
        if re.search(r'\buse\s+[^;]*$',src[:u.start()].split(';')[-1]): continue
        t=resolve(m,u.group(1))
        if t is not None and t!=m and t!='' and not t.startswith(m+'::') and not through_top_face(m,t):
            edges.setdefault(m,set()).add(t)
# a folder's face (mod.rs) depends on the children it declares and re-exports
for m,f in mods.items():
    if f.endswith('mod.rs'):
        src=re.sub(r'//.*','',open(f).read().split('#[cfg(test)]')[0])
        for c in re.findall(r'^\s*(?:pub(?:\([a-z]+\))?\s+)?mod\s+([a-z_0-9]+)\s*;',src,re.M):
            child=(m+'::'+c) if m else c
            if child in mods: edges.setdefault(m,set()).add(child)
# Tarjan SCC
index={};low={};st=[];on=set();sccs=[];i=[0]
sys.setrecursionlimit(10000)
def sc(v):
    index[v]=low[v]=i[0];i[0]+=1;st.append(v);on.add(v)
    for w in edges.get(v,()):
        if w not in index: sc(w);low[v]=min(low[v],low[w])
        elif w in on: low[v]=min(low[v],index[w])
    if low[v]==index[v]:
        comp=[]
        while True:
            w=st.pop();on.discard(w);comp.append(w)
            if w==v:break
        if len(comp)>1: sccs.append(comp)
for v in list(mods): 
    if v not in index: sc(v)
failing=[]
for c in sccs:
    reason=ALLOWED.get(frozenset(full_prefix+v for v in c))
    if reason:
        print('allowed cycle:', ' '.join(sorted(c)), '--', reason)
    else:
        print('cycle:', ' '.join(sorted(c)))
        failing.append(c)
        if os.environ.get('CYCLE_EDGES'):
            members=set(c)
            for a in sorted(c):
                for b in sorted(edges.get(a,())):
                    if b in members: print('   ',a,'->',b)
print(f'{root}: {len(mods)} modules, {sum(len(e) for e in edges.values())} edges, '
      f'{len(failing)} cycles ({len(sccs)-len(failing)} allowed)')
sys.exit(1 if failing else 0)
