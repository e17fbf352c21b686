# Prescribed motion: fix move drives the bottom layer of a 4x4x3 stack of grains sideways
# while fix move/mesh drives a lid mesh down onto the stack (the grains push back on the
# lid).   -var meshes <mesh dir>
atom_style      granular
atom_modify     map array
boundary        p p f
newton          off
communicate     single vel yes
units           si
region          box block 0 0.04 0 0.04 -0.001 0.06 units box
create_box      2 box
neighbor        0.002 bin
neigh_modify    delay 0

fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.45 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.3 0.3 0.3 0.3
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0 0 0
fix m5 all property/global characteristicVelocity scalar 0.5
pair_style      gran model hertz tangential history
pair_coeff      * *

lattice         sc 0.01
region          fill block 0 0.04 0 0.04 0.004 0.031 units box
create_atoms    1 region fill
set             group all diameter 0.01 density 2500
region          bottom block INF INF INF INF INF 0.015 units box
group           base region bottom
group           free subtract all base

fix             floor all mesh/surface file ${meshes}/unit_square.stl type 2 scale 0.04 move 0 0 0.005
fix             lid all mesh/surface/stress file ${meshes}/unit_square.stl type 2 scale 0.04 &
                move 0 0 0.0355 reference_point 0.02 0.02 0.0355
fix             walls all wall/gran model hertz tangential no_history mesh n_meshes 2 meshes floor lid
fix             press all move/mesh mesh lid linear 0 0 -0.02

timestep        1e-5
fix             integrate free nve/sphere
fix             g free gravity 9.81 vector 0 0 -1
fix             shear base move linear 0.02 0 0

variable        x1 equal x[1]
variable        y1 equal y[1]
variable        z1 equal z[1]
thermo_style    custom step atoms f_lid[3] f_lid[9] v_x1 v_y1 v_z1
thermo_modify   format float %.15g
thermo          500
run             15000
