import math
class W:
    def __init__(s): s.lines=[]; s.n=0
    def add(s, text):
        s.n+=1; s.lines.append(f"#{s.n}={text};"); return s.n
    def pt(s,p): return s.add("CARTESIAN_POINT('',(%s))"%",".join(repr(float(x)) for x in p))
    def dir(s,d): return s.add("DIRECTION('',(%s))"%",".join(repr(float(x)) for x in d))
    def place(s,o,z,x): return s.add(f"AXIS2_PLACEMENT_3D('',#{s.pt(o)},#{s.dir(z)},#{s.dir(x)})")
    def vertex(s,p): return s.add(f"VERTEX_POINT('',#{s.pt(p)})")
    def line_edge(s,va,vb,pa,pb):
        d=[b-a for a,b in zip(pa,pb)]; L=math.sqrt(sum(x*x for x in d)); u=[x/L for x in d]
        vec=s.add("VECTOR('',#%d,%r)"%(s.dir(u),L))
        ln=s.add(f"LINE('',#{s.pt(pa)},#{vec})")
        return s.add(f"EDGE_CURVE('',#{va},#{vb},#{ln},.T.)")
    def circle_edge(s,va,vb,o,z,x,r,same=True):
        c=s.add(f"CIRCLE('',#{s.place(o,z,x)},{float(r)!r})")
        return s.add(f"EDGE_CURVE('',#{va},#{vb},#{c},{'.T.' if same else '.F.'})")
    def loop(s,edges,outer=True,orient=True):
        oe=[s.add(f"ORIENTED_EDGE('',*,*,#{e},{'.T.' if o else '.F.'})") for e,o in edges]
        lp=s.add("EDGE_LOOP('',(%s))"%",".join(f"#{i}" for i in oe))
        return s.add(f"{'FACE_OUTER_BOUND' if outer else 'FACE_BOUND'}('',#{lp},{'.T.' if orient else '.F.'})")
    def face(s,name,bounds,surf,same=True):
        return s.add(f"ADVANCED_FACE('{name}',(%s),#{surf},{'.T.' if same else '.F.'})"%",".join(f"#{b}" for b in bounds))
    def text(s,desc):
        return ("ISO-10303-21;\nHEADER;\n/* "+desc+" */\nFILE_DESCRIPTION(('ssimarch trimming-loop test'),'2;1');\n"
          "FILE_NAME('t','2026-12-02T08:30:00',('ssimarch tests'),(''),'tests/step/data generator','ssimarch','');\n"
          "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n"+"\n".join(s.lines)+"\nENDSEC;\nEND-ISO-10303-21;\n")

def square(w, o, e0, e1, h):
    pts=[[o[k]+a*h*e0[k]+b*h*e1[k] for k in range(3)] for a,b in [(-1,-1),(1,-1),(1,1),(-1,1)]]
    vs=[w.vertex(p) for p in pts]
    return [(w.line_edge(vs[i],vs[(i+1)%4],pts[i],pts[(i+1)%4]),True) for i in range(4)]

def cyl_full(w, o, axis, ref, r, length):
    # a whole cylinder face between two rims (seam line used twice)
    top=[o[k]+length*axis[k] for k in range(3)]
    p0=[o[k]+r*ref[k] for k in range(3)]; p1=[top[k]+r*ref[k] for k in range(3)]
    v0=w.vertex(p0); v1=w.vertex(p1)
    rim0=w.circle_edge(v0,v0,o,axis,ref,r); rim1=w.circle_edge(v1,v1,top,axis,ref,r)
    seam=w.line_edge(v0,v1,p0,p1)
    b=w.loop([(rim0,True),(seam,True),(rim1,False),(seam,False)])
    surf=w.add(f"CYLINDRICAL_SURFACE('',#{w.place(o,axis,ref)},{float(r)!r})")
    return w.face('cylinder',[b],surf)

def plate_with_a_hole(w):
    # the square z = 0, |x|, |y| <= 3, with a hole of radius 1 at the origin
    sq=square(w,[0,0,0],[1,0,0],[0,1,0],3.0)
    outer=w.loop(sq)
    v5=w.vertex([1,0,0]); hole=w.circle_edge(v5,v5,[0,0,0],[0,0,1],[1,0,0],1.0)
    inner=w.loop([(hole,False)],outer=False)
    plane=w.add(f"PLANE('',#{w.place([0,0,0],[0,0,1],[1,0,0])})")
    return w.face('plate',[outer,inner],plane)

# 1. plate with a hole, and a cylinder across it
w=W()
plate_with_a_hole(w)
cyl_full(w,[-2.5,0,0.3],[1,0,0],[0,0,-1],0.5,5.0)
open('plate_with_hole.step','w').write(w.text("A square plate z = 0, |x|, |y| <= 3, with a hole of radius 1 at the origin (face 1), and a whole cylinder face y^2 + (z - 0.3)^2 = 0.25, -2.5 <= x <= 2.5 (face 2)."))

# 1b. a rod in a hole of its own radius: the plate of model 1 and a whole cylinder face
# x^2 + y^2 = r^2, -1 <= z <= 1, whose radius is the hole's, or 1e-9 less (a CAD model's faces meet
# along an edge to the model's accuracy, not exactly)
for name, r in (("rod_in_hole.step", 1.0), ("rod_in_hole_tight.step", 1.0 - 1e-9)):
    w=W()
    plate_with_a_hole(w)
    cyl_full(w,[0,0,-1],[0,0,1],[1,0,0],r,2.0)
    open(name,'w').write(w.text("The plate z = 0, |x|, |y| <= 3, with a hole of radius 1 at the origin (face 1), and a whole cylinder face x^2 + y^2 = %r^2, -1 <= z <= 1 (face 2): the rod meets the plate along the hole's edge." % r))

# 2. half cylinder (y >= 0) and an inclined plane
w=W()
a0=w.vertex([1,0,0]); a1=w.vertex([-1,0,0]); b0=w.vertex([1,0,2]); b1=w.vertex([-1,0,2])
bottom=w.circle_edge(a0,a1,[0,0,0],[0,0,1],[1,0,0],1.0,True)
top=w.circle_edge(b1,b0,[0,0,2],[0,0,1],[1,0,0],1.0,False)
left=w.line_edge(a1,b1,[-1,0,0],[-1,0,2]); right=w.line_edge(b0,a0,[1,0,2],[1,0,0])
b=w.loop([(bottom,True),(left,True),(top,True),(right,True)])
surf=w.add(f"CYLINDRICAL_SURFACE('',#{w.place([0,0,0],[0,0,1],[1,0,0])},1.0)")
w.face('half cylinder',[b],surf)
n=[-0.3,0,1]; L=math.sqrt(sum(x*x for x in n)); n=[x/L for x in n]
e0=[1,0,0.3]; L=math.sqrt(sum(x*x for x in e0)); e0=[x/L for x in e0]
e1=[n[1]*e0[2]-n[2]*e0[1], n[2]*e0[0]-n[0]*e0[2], n[0]*e0[1]-n[1]*e0[0]]
sq=square(w,[0,0,1],e0,e1,3.0)
outer=w.loop(sq)
plane=w.add(f"PLANE('',#{w.place([0,0,1],n,e0)})")
w.face('inclined plane',[outer],plane)
open('half_cylinder_cut.step','w').write(w.text("Half of the cylinder x^2 + y^2 = 1, y >= 0, 0 <= z <= 2 (face 1: two half circles, two lines), and the plane z = 1 + 0.3 x (face 2, a square of side 6)."))

# 3. an assembly: one rod part placed three times, a plate, a sub-assembly (docs/cad.md, "Assemblies")
w=W()
ctx=w.add("REPRESENTATION_CONTEXT('3D','3D')")
def closed_solid(w, faces):
    shell=w.add("CLOSED_SHELL('',(%s))"%",".join(f"#{f}" for f in faces))
    return w.add(f"MANIFOLD_SOLID_BREP('',#{shell})")
def product(w, name):
    p=w.add(f"PRODUCT('{name}','{name}','',())")
    f=w.add(f"PRODUCT_DEFINITION_FORMATION('','',#{p})")
    return w.add(f"PRODUCT_DEFINITION('design','',#{f},$)")
def shape_of(w, pd, rep):
    pds=w.add(f"PRODUCT_DEFINITION_SHAPE('','',#{pd})")
    w.add(f"SHAPE_DEFINITION_REPRESENTATION(#{pds},#{rep})")
def occurrence(w, k, name, parent_pd, child_pd, rep1, rep2, item1, item2):
    nauo=w.add(f"NEXT_ASSEMBLY_USAGE_OCCURRENCE('{k}','{name}','',#{parent_pd},#{child_pd},$)")
    pds=w.add(f"PRODUCT_DEFINITION_SHAPE('Placement','',#{nauo})")
    idt=w.add(f"ITEM_DEFINED_TRANSFORMATION('','',#{item1},#{item2})")
    rr=w.add(f"(REPRESENTATION_RELATIONSHIP('','',#{rep1},#{rep2})REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#{idt})SHAPE_REPRESENTATION_RELATIONSHIP())")
    w.add(f"CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#{rr},#{pds})")
# the rod: the cylinder x^2 + y^2 = 1, 0 <= z <= 10, in its own coordinates
rod_face=cyl_full(w,[0,0,0],[0,0,1],[1,0,0],1.0,10.0)
rod_origin=w.place([0,0,0],[0,0,1],[1,0,0])
rod_rep=w.add(f"ADVANCED_BREP_SHAPE_REPRESENTATION('rod',(#{rod_origin},#{closed_solid(w,[rod_face])}),#{ctx})")
# the plate: z = 0, |x|, |y| <= 20
sq=square(w,[0,0,0],[1,0,0],[0,1,0],20.0)
plate_face=w.face('plate',[w.loop(sq)],w.add(f"PLANE('',#{w.place([0,0,0],[0,0,1],[1,0,0])})"))
plate_origin=w.place([0,0,0],[0,0,1],[1,0,0])
open_shell=w.add(f"OPEN_SHELL('',(#{plate_face}))")
plate_shell=w.add(f"SHELL_BASED_SURFACE_MODEL('',(#{open_shell}))")
plate_geometry=w.add(f"MANIFOLD_SURFACE_SHAPE_REPRESENTATION('plate',(#{plate_origin},#{plate_shell}),#{ctx})")
plate_rep=w.add(f"SHAPE_REPRESENTATION('plate',(#{plate_origin}),#{ctx})")
w.add(f"SHAPE_REPRESENTATION_RELATIONSHIP('','',#{plate_rep},#{plate_geometry})")
# the sub-assembly: the rod along its +x axis (local z -> x)
sub_origin=w.place([0,0,0],[0,0,1],[1,0,0])
in_sub=w.place([0,0,0],[1,0,0],[0,0,1])
sub_rep=w.add(f"SHAPE_REPRESENTATION('sub',(#{sub_origin},#{in_sub}),#{ctx})")
# the root: rod_1 at (5, 0, -2); plate_1 in place; sub_1 turned 90 degrees about z and moved to
# (0, -5, 0.5) (its relationship written with rep_1 and rep_2 swapped, as some writers do); rod_3
# by a MAPPED_ITEM at (-5, 0, -2)
root_origin=w.place([0,0,0],[0,0,1],[1,0,0])
at_rod1=w.place([5,0,-2],[0,0,1],[1,0,0]); at_plate=w.place([0,0,0],[0,0,1],[1,0,0]); at_sub=w.place([0,-5,0.5],[0,0,1],[0,1,0])
rod3_map=w.add(f"REPRESENTATION_MAP(#{rod_origin},#{rod_rep})")
rod3=w.add(f"MAPPED_ITEM('rod_3',#{rod3_map},#{w.place([-5,0,-2],[0,0,1],[1,0,0])})")
root_rep=w.add(f"SHAPE_REPRESENTATION('root',(#{root_origin},#{at_rod1},#{at_plate},#{at_sub},#{rod3}),#{ctx})")
root_pd=product(w,'root'); rod_pd=product(w,'rod'); plate_pd=product(w,'plate'); sub_pd=product(w,'sub')
shape_of(w,root_pd,root_rep); shape_of(w,rod_pd,rod_rep); shape_of(w,plate_pd,plate_rep); shape_of(w,sub_pd,sub_rep)
occurrence(w,'1','rod_1',root_pd,rod_pd,rod_rep,root_rep,rod_origin,at_rod1)
occurrence(w,'2','plate_1',root_pd,plate_pd,plate_rep,root_rep,plate_origin,at_plate)
occurrence(w,'3','sub_1',root_pd,sub_pd,root_rep,sub_rep,at_sub,sub_origin)
occurrence(w,'4','rod_2',sub_pd,rod_pd,rod_rep,sub_rep,rod_origin,in_sub)
open('rod_assembly.step','w').write(w.text("An assembly (root): the rod (a cylinder of radius 1 on its z axis, 0 <= z <= 10) as rod_1 at (5, 0, -2), as sub_1/rod_2 along y through (0, -5, 0.5) (sub_1 turned 90 degrees about z, the rod along sub's x) and as rod_3 (a MAPPED_ITEM) at (-5, 0, -2); the plate z = 0, |x|, |y| <= 20 as plate_1."))

# 6. two faces of a block sharing an edge: the pentagon z = 0 with corners (-1, -1), (1, -1),
# (1, 0.5), (0.5, 1), (-1, 1) (face 1) and the rectangle x = 1, |y| <= 1, 0 <= z <= 2 (face 2);
# they share x = 1, z = 0, -1 <= y <= 0.5, each with its own edges
w=W()
def polygon_face(w, name, pts, place):
    vs=[w.vertex(p) for p in pts]
    edges=[(w.line_edge(vs[i],vs[(i+1)%len(pts)],pts[i],pts[(i+1)%len(pts)]),True) for i in range(len(pts))]
    return w.face(name,[w.loop(edges)],w.add(f"PLANE('',#{w.place(*place)})"))
polygon_face(w,'bottom',[[-1,-1,0],[1,-1,0],[1,0.5,0],[0.5,1,0],[-1,1,0]],([0,0,0],[0,0,1],[1,0,0]))
polygon_face(w,'side',[[1,-1,0],[1,1,0],[1,1,2],[1,-1,2]],([1,0,1],[1,0,0],[0,1,0]))
open('block_edge.step','w').write(w.text("Two faces of a block sharing the edge x = 1, z = 0, -1 <= y <= 0.5: the pentagon z = 0 with corners (-1, -1), (1, -1), (1, 0.5), (0.5, 1), (-1, 1) (face 1) and the rectangle x = 1, |y| <= 1, 0 <= z <= 2 (face 2)."))

# 7. a quarter of the outer half of a torus (R = 2, r = 0.5 about z): 0 <= u <= pi/2 around the
# axis, -pi/2 <= v <= pi/2 around the tube; bounded by two arcs of radius 2 at z = -+0.5 and two
# half circles of the tube at u = 0 and u = pi/2
w=W()
R,r=2.0,0.5
p00=[R,0,-r]; p10=[0,R,-r]; p11=[0,R,r]; p01=[R,0,r]
va,vb,vc,vd=[w.vertex(p) for p in (p00,p10,p11,p01)]
bottom=w.circle_edge(va,vb,[0,0,-r],[0,0,1],[1,0,0],R)
side1=w.circle_edge(vb,vc,[0,R,0],[1,0,0],[0,1,0],r)
top=w.circle_edge(vd,vc,[0,0,r],[0,0,1],[1,0,0],R)
side0=w.circle_edge(va,vd,[R,0,0],[0,-1,0],[1,0,0],r)
loop=w.loop([(bottom,True),(side1,True),(top,False),(side0,False)])
torus=w.add(f"TOROIDAL_SURFACE('',#{w.place([0,0,0],[0,0,1],[1,0,0])},{R!r},{r!r})")
w.face('torus_patch',[loop],torus)
open('torus_patch.step','w').write(w.text("A quarter of the outer half of the torus R = 2, r = 0.5 about z: 0 <= u <= pi/2, -pi/2 <= v <= pi/2 (face 1)."))

# 8. two solids (MANIFOLD_SOLID_BREP, CLOSED_SHELL) for the faces of one solid (docs/cad.md, "Faces
# of one solid"): faces 1-8 the octahedron |x - 5| + |y| + |z| <= 1, each face the triangle of one
# octant (signs of x - 5, y, z in binary order -, +), its normal outward; faces 9-12 the puck
# x^2 + y^2 <= 1, 0 <= z <= 1: the half cylinders y >= 0 (face 9) and y <= 0 (face 10), which share
# the lines x = +-1, y = 0, the bottom z = 0 (face 11) and the top z = 1 (face 12).
w=W()
c=[5.0,0,0]
ov={}
for k in range(3):
    for sg in (1,-1):
        p=list(c); p[k]+=sg; ov[(k,sg)]=(w.vertex(p),p)
oedges={}
def oedge(a,b):
    key=tuple(sorted([a,b]))
    if key not in oedges:
        (va,pa),(vb,pb)=ov[key[0]],ov[key[1]]
        oedges[key]=w.line_edge(va,vb,pa,pb)
    return oedges[key],(a,b)==key
octa=[]
for sx in (-1,1):
    for sy in (-1,1):
        for sz in (-1,1):
            tri=[(0,sx),(1,sy),(2,sz)]
            if sx*sy*sz<0: tri=[tri[0],tri[2],tri[1]]  # counter-clockwise seen from outside
            loop=w.loop([oedge(tri[i],tri[(i+1)%3]) for i in range(3)])
            n=[sx/math.sqrt(3),sy/math.sqrt(3),sz/math.sqrt(3)]
            p0=ov[tri[0]][1]; e=[ov[tri[1]][1][k]-p0[k] for k in range(3)]; L=math.sqrt(sum(x*x for x in e))
            plane=w.add(f"PLANE('',#{w.place(p0,n,[x/L for x in e])})")
            octa.append(w.face('octant',[loop],plane))
w.add("MANIFOLD_SOLID_BREP('octahedron',#%d)"%w.add("CLOSED_SHELL('',(%s))"%",".join(f"#{f}" for f in octa)))
pa,pb,pc,pd=[1,0,0],[-1,0,0],[1,0,1],[-1,0,1]
va,vb,vc,vd=[w.vertex(p) for p in (pa,pb,pc,pd)]
arc1=w.circle_edge(va,vb,[0,0,0],[0,0,1],[1,0,0],1.0)
arc2=w.circle_edge(vb,va,[0,0,0],[0,0,1],[1,0,0],1.0)
arc3=w.circle_edge(vc,vd,[0,0,1],[0,0,1],[1,0,0],1.0)
arc4=w.circle_edge(vd,vc,[0,0,1],[0,0,1],[1,0,0],1.0)
l1=w.line_edge(va,vc,pa,pc); l2=w.line_edge(vb,vd,pb,pd)
def cylinder(): return w.add(f"CYLINDRICAL_SURFACE('',#{w.place([0,0,0],[0,0,1],[1,0,0])},1.0)")
puck=[w.face('half_y_pos',[w.loop([(arc1,True),(l2,True),(arc3,False),(l1,False)])],cylinder()),
      w.face('half_y_neg',[w.loop([(arc2,True),(l1,True),(arc4,False),(l2,False)])],cylinder()),
      w.face('bottom',[w.loop([(arc2,False),(arc1,False)])],w.add(f"PLANE('',#{w.place([0,0,0],[0,0,-1],[1,0,0])})")),
      w.face('top',[w.loop([(arc3,True),(arc4,True)])],w.add(f"PLANE('',#{w.place([0,0,1],[0,0,1],[1,0,0])})"))]
w.add("MANIFOLD_SOLID_BREP('puck',#%d)"%w.add("CLOSED_SHELL('',(%s))"%",".join(f"#{f}" for f in puck)))
open('solids.step','w').write(w.text("Two solids: the octahedron |x - 5| + |y| + |z| <= 1 (faces 1-8, one per octant) and the puck x^2 + y^2 <= 1, 0 <= z <= 1 (faces 9, 10 the half cylinders y >= 0 and y <= 0, 11 the bottom, 12 the top)."))
