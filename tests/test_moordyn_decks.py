"""MoorDyn decks as MoorDyn-C 2.7 reads them (issue 30, part 1); no moordyn package needed.

The fixtures are the line decks of MoorDyn's own test suite (FloatingArrayDesign/MoorDyn,
tests/Mooring/) and of MoorPy's examples and tests (NREL/MoorPy, examples/, tests/),
typed here by hand in our own layout with their numbers kept (headers, option names and
comment characters as in the originals, since those are what is being read). Each one
imports, or is refused with one line (exit 2) naming the deck line and the feature.

What MoorDyn-C 2.7 does, which these tests hold the importer to (source/MoorDyn2.cpp, and
measured on moordyn 2.7.2 from the weight per metre of a line under each option):
g = 9.80665 m/s2 and a density of 1025 kg/m3 unless the deck gives g/gravity and
rho/Rho/WtrDnsty (never rhoW, MoorDyn-F's name); option names in any case, the last row
wins; a section header is any line with '---' and a key phrase ("SOLVER OPTIONS" is the
OPTIONS); a section ends at the next '---' line ("need this line"); WtrDpth defaults to 0
and is lowered to the deepest point; "1,5e9" is 1 to C's atof.

Numbers read from a deck are compared exactly (==): the importer copies them; a derived
number (kBot x Diam, a damping ratio) to 1e-12, the rounding of two or three operations.
"""

from __future__ import annotations

import math
import re

import pytest

from riser.io.moordyn.deck_from_scene import export_scene
from riser.io.scene_file import load_scene
from verification.catalog import resolve
from verification.cli import main

# ----------------------------------------------------------------- MoorDyn's test decks
LINES_OC3 = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input file of the mooring system for OC3-Hywind
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
main  0.09  77.7066  384.243E6  -0.8  0  1.6  1.0  0.1  0.0
---------------------- POINT PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed   853.87   0        -320.0  0  0  0  0
2  Fixed   -426.94  739.47   -320.0  0  0  0  0
3  Fixed   -426.94  -739.47  -320.0  0  0  0  0
4  Vessel  5.2      0.0      -70.0   0  0  0  0
5  Vessel  -2.6     4.5      -70.0   0  0  0  0
6  Vessel  -2.6     -4.5     -70.0   0  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  main  1  4  902.2  20  -
2  main  2  5  902.2  20  -
3  main  3  6  902.2  20  -
---------------------- OPTIONS -----------------------------------------
2             writeLog       Write a log file
0.002         dtM            time step to use in mooring integration (s)
3.0e6         kBot           bottom stiffness (Pa/m)
3.0e5         cBot           bottom damping (Pa-s/m)
1025.0        WtrDnsty       water density (kg/m^3)
320           WtrDpth        water depth (m)
1.0           dtIC           time interval for analyzing convergence during IC gen (s)
100.0         TmaxIC         max time for ic gen (s)
4.0           CdScaleIC      factor by which to scale drag coefficients (-)
0.001         threshIC       threshold for IC convergence (-)
lines.txt.ic  fileIC         Load a quasistatic solution before the IC solver (-)
1             disableOutTime
------------------------- need this line --------------------------------------
"""

WD0050_CHAIN = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input file of the mooring system for FD validation cases
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain  0.252  390  1.674e9  -1.0  0  1.37  1.0  0.64  0.0
---------------------- POINT PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed   400  0.0  -50.0  0  0  0  0
2  Vessel  0.0  0.0  0.0    0  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  chain  1  2  410  82  -
---------------------- OPTIONS -----------------------------------------
2       writeLog             Write a log file
0.001   dtM                  time step to use in mooring integration (s)
1.0e5   kBot                 bottom stiffness (Pa/m)
1.0e4   cBot                 bottom damping (Pa-s/m)
1025.0  WtrDnsty             water density (kg/m^3)
50      WtrDpth              water depth (m)
1.0     dtIC                 time interval for analyzing convergence during IC gen (s)
200.0   TmaxIC               max time for ic gen (s)
4.0     CdScaleIC            factor by which to scale drag coefficients (-)
1.0e-3  threshIC             threshold for IC convergence (-)
0.5     FrictionCoefficient  general bottom friction coefficient, as a start (-)
------------------------- need this line --------------------------------------
"""

RISER = """\
riser.txt: The riser actual simulation
------------------------- LINE TYPES --------------------------------------------------
LineType Diam MassDenInAir EA BA/-zeta EI Can Cat Cdn Cdt
(-) (m) (kg/m) (N) (Pa-s/-) (n-m^2) (-) (-) (-) (-)
cable     0.116  25  362e6  -1.0  38e3  1.0  0.0    1.1    0.008
bouyancy  0.361  59  362e6  -1.0  38e3  1.0  0.469  2.617  0.345
nylon     0.116  25  362e6  -1.0  38e3  1.0  0.0    1.1    0.008
---------------------- ROD TYPES ------------------------------------
TypeName Diam Mass/m Cd Ca CdEnd CaEnd
(name) (m) (kg/m) (-) (-) (-) (-)
conn        0.116  25  1.1  1.0  1.1  1.0
conn_stiff  0.116  25  1.1  1.0  1.1  1.0
clamp       0.116  25  1.2  1.0  1.2  1.0
---------------------------- BODIES -----------------------------------------------------
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1  Free  452.0  0  -313.0  0  0  0  29.5  0  0.098  0.014  0.5|0.5  1.0
---------------------- RODS ----------------------------------------
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
1  clamp  Body1  0.1    0  0.0     -0.1   0  0.0     1  -
2  conn   Free   375.0  0  -250.0  375.0  0  -250.0  0  -
3  conn   Free   290.0  0  -215.0  290.0  0  -215.0  0  -
----------------------- POINTS ----------------------------------------------
Node Type X Y Z M V CdA CA
(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed    600.0  0  -320.0  0  0  0  0
2  Fixed    452.0  0  -320.0  0  0  0  0
3  Body1    0.0    0  0.0     0  0  0  0
4  Coupled  0.0    0  -63.6   0  0  0  0
-------------------------- LINES -------------------------------------------------
Line LineType NodeA NodeB UnstrLen NumSegs Flags/Outputs
(-) (-) (-) (-) (m) (-) (-)
1  nylon     2    3    7.0    1   -
2  cable     1    R1A  150.0  15  -
3  cable     R1B  R2A  110.0  11  -
4  bouyancy  R2B  R3A  80.0   8   -
5  cable     R3B  4    340.0  34  -
-------------------------- SOLVER OPTIONS---------------------------------------------------
3.0e6      kb            - bottom stiffness
3.0e5      cb            - bottom damping
320        WtrDpth       - water depth
midpoint5  tScheme       - Time integrator
0.5        cfl           - Courant-Friedich-Lewy factor
0          ICgenDynamic  - 0 for stationary solver, 1 for upscaled drag legacy solver
4.0        ICDfac        - factor by which to scale drag coefficients during IC gen
1e-3       threshIC      - threshold for IC convergence
1.0        dtIC          - Time lapse between convergence tests (s)
1.0        TmaxIC        - threshold for IC convergence
riser.ic   fileIC        - Load a quasistatic solution before the IC solver (-)
--------------------------- need this line -------------------------------------------------
"""

LOWE_LANGLEY = """\
MoorDyn input file for a flexible jumper (Lowe and Langley, 2006)
True   Echo   echo the input file data (flag)
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
main  0.396  165.0  500.0e6  -0.5  120.8e3  1.0  1.0  0.0  0.0
---------------------- CONNECTION PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed    -100  0  -55  0  0  0  0
2  Coupled  0     0  -5   0  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  main  1  2  170  68  -
---------------------- OPTIONS -----------------------------------------
0          writeLog      Write a log file
0.001      dtM           Model time step (s)
3.0e6      kBot          bottom stiffness (Pa/m)
3.0e5      cBot          bottom damping (Pa-s/m)
100        WtrDpth       water depth (m)
1000.0     WtrDnsty      water density (kg/m^3)
9.807      g             gravity (m/s^2)
midpoint5  tScheme       Time integration scheme
5.0        CdScaleIC     Initial Condition generation drag factor
30         TmaxIC        Initial Condition generation maximum time (s)
1.0        dtIC          Initial Condition generation convergence tests (s)
5e-3       threshIC      Initial Condition generation convergence threshold
0          ICgenDynamic  IC generator (0 = stationary, 1 = legacy upscale dynamics)
1          WaveKin       The wave kinematics are provided through the API (-)
1          disableOutTime
------------------------- need this line --------------------------------------
"""
#: the same jumper without its WaveKin row: a riser scene
LOWE_LANGLEY_STILL = LOWE_LANGLEY.replace(
    "1          WaveKin       The wave kinematics are provided through the API (-)\n", "")

BEAM_SIMPLY_SUPPORTED = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input file of the mooring system for FD validation cases
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
beam  0.25  100.0  1.5e9  -1.0  1e7  0.0  0.0  0.1  0.0
---------------------- POINT PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed  0   0.0  10.0  0  0  0  0
2  Fixed  10  0.0  10.0  0  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  beam  1  2  10  19  -
---------------------- OPTIONS -----------------------------------------
2     writeLog  Write a log file
0.1   cfl       CFL to determine the simulation timestep
10    WtrDpth   water depth (m)
1.0   dtIC      time interval for analyzing convergence during IC gen (s)
40.0  TmaxIC    max time for ic gen (s)
1e-5  threshIC  threshold for IC convergence (-)
------------------------- need this line --------------------------------------
"""

BEAM_CANTILEVERED = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input file of the mooring system for FD validation cases
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
beam  0.05  100.0  1.5e9  -1.0  1e7  0.0  0.0  0.1  0.0
---------------------- ROD TYPES ------------------------------------
TypeName Diam Mass/m Cd Ca CdEnd CaEnd
(name) (m) (kg/m) (-) (-) (-) (-)
cantilever  0.25  100.0  0.0  0.0  0.0  0.0
---------------------- RODS ----------------------------------------
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
1  cantilever  Fixed  -10.0  0  10.0  0.0  0  10.0  1  -
---------------------- CONNECTION PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Free  10  0.0  10.0  0  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  beam  R1B  1  10  19  -
---------------------- OPTIONS -----------------------------------------
2       writeLog   Write a log file
1e-5    dtM        time step to use in mooring integration (s)
10      WtrDpth    water depth (m)
0.25    dtIC       time interval for analyzing convergence during IC gen (s)
50.0    TmaxIC     max time for ic gen (s)
1.0     CdScaleIC  factor by which to scale drag coefficients (-)
1.0e-3  threshIC   threshold for IC convergence (-)
------------------------- need this line --------------------------------------
"""

VIV = """\
From Thorsen Paper 4 uniform current
Catenary riser in a steady flow from validation paper
---------------------- LINE DICTIONARY -----------------------------------------------------
LineType Diam MassDenInAir EA cIntDamp EI Cd Ca CdAx CaAx Cl
(-) (m) (kg/m) (N) (Pa-s) (N-m^2) (-) (-) (-) (-) (-)
cable  0.024  0.69  6.66e5  -1  10.5  1.2  2.0  0.08  0.08  0.7 #
---------------------- POINTS -----------------------------------------------------
Node Type X Y Z M V CdA Ca
(-) (-) (m) (m) (m) (kg) (m^3) (m2) ()
1  Fixed  -21.0425  0  -10  0  0  0  0
2  Fixed  0         0  -1   0  0  0  0
---------------------- LINES -----------------------------------------------------
Line LineType NodeA NodeB UnstrLen NumSegs Flags/Outputs
(-) (-) (-) (-) (m) (-) (-)
1  cable  1  2  23.71  100  -
---------------------- SOLVER OPTIONS ----------------------------------------
2       writeLog
Rk4     tScheme
0.0001  dtM                  - time step to use in mooring integration
1.5e5   kb                   - bottom stiffness
1e4     cb                   - bottom damping
0.5     FrictionCoefficient  - seabed friction
20000   FricDamp             - Friction damping coefficient
10      WtrDpth              - water depth
1.0     CdScaleIC            - factor by which to scale drag coefficients
0.001   threshIC             - threshold for IC convergence
2       dtIC
100     TmaxIC               - threshold for IC convergence
1       ICgenDynamic
0.001   dtOut
1000    WtrDnsty
1       Currents
1       disableOutTime
---------------------- need this line -----------------------------------------
"""
#: viv/current_profile.txt: 0.2 m/s along X at 50 depths from -11 m to 0 (numpy's
#: linspace(-11, 0, 50), as the original's rows are), written as MoorDyn writes it
VIV_CURRENT = ("--------------------- MoorDyn steady currents File ---------------------\n"
               "Tabulated file with the water currents components\n"
               "z (m), ux (m/s), uy (m/s), uz (m/s)\n"
               + "".join(f"{-11.0 + 11.0 * i / 49!r} 0.2 0 0\n" for i in range(50)))

VISCO = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input file for Polyester stiffness and length variation as a function
of the tension. Uses the MD viscoelastic load dependent dynamic stiffness model.

EA_s = KRS * MBL = 13.4 * 25.3e6 = 3.39e8
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
Polyester_290mm  0.217  52.0  3.39e8|4.048e8|8.855e6  -1.0|1e11  0.0  1.6  1.79  0.008  0.0
---------------------- POINT PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed    0.0     0.0  -372.192  0.0  0.0  0.0  0.0
2  Coupled  1360.0  0.0  -18.0     0.0  0.0  0.0  0.0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  Polyester_290mm  1  2  1400.0  70  p
---------------------- OPTIONS -----------------------------------------
2          writeLog             Write a log file
0.0005     dtM                  time step to use in mooring integration (s)
1.0e5      kBot                 bottom stiffness (Pa/m)
1.0e4      cBot                 bottom damping (Pa-s/m)
9.80665    g                    gravitational constant (m/s^2)
1025.0     WtrDnsty             water density (kg/m^3)
372.3      WtrDpth              water depth (m)
4.0        CdScaleIC            factor by which to scale drag coefficients (-)
1          ICgenDynamic
0.5        FrictionCoefficient  general bottom friction coefficient, as a start (-)
5.0        dtIC                 time interval for analyzing convergence during IC gen (s)
00         TmaxIC               max time for ic gen (s)
0.0000001  threshIC             threshold for IC convergence (-)
0.001      dtOut
------------------------- Outputs -------------------------
Fairten1
POINT1PX
------------------------- need this line --------------------------------------
"""

PENDULUM = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input for a simple pendulum. The conection line is almost weightless,
i.e. it has the same density than water, and it has 0 damping
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
main  0.1  7.85398  1.0E9  -0.01  0  0.0  0.0  0.0  0.0
---------------------- POINT PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed  0   0  0     0    0  0  0
2  Free   10  0  -100  1E5  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  main  1  2  100.5  20  -
---------------------- OPTIONS -----------------------------------------
2        writeLog      Write a log file
0.1      cfl           CFL to determine the simulation timestep
RK4      tScheme       The time integration Scheme (-)
1000.0   WtrDnsty      water density (kg/m^3)
500      WtrDpth       water depth (m)
1.0      dtIC          time interval for analyzing convergence during IC gen (s)
10000.0  TmaxIC        max time for ic gen (s)
1e-4     threshIC      threshold for IC convergence (-)
0        ICgenDynamic  IC generator (0 = stationary, 1 = legacy upscale dynamics)
------------------------- need this line --------------------------------------
"""

SEAFLOOR = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input for a pendulum that will collide with a 3D seafloor. The conection
line is almost weightless, i.e. it has the same density than water,and it has 0 damping
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
main  0.1  7.85398  1.0E9  -0.01  0  0.0  0.0  0.0  0.0
---------------------- CONNECTION PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed  0   -1  0    0    0  0  0
2  Free   10  -1  -28  1E1  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  main  1  2  32.0  20  p
---------------------- OPTIONS -----------------------------------------
2        writeLog      Write a log file
1E-4     dtM           time step to use in mooring integration (s)
RK4      tScheme       The time integration Scheme (-)
1000.0   WtrDnsty      water density (kg/m^3)
500      WtrDpth       water depth (m)
Mooring/3D_seafloor/seafloor_profile_3d.txt  SeafloorFile  3D seafloor file path
1E-3     dtIC          time interval for analyzing convergence during IC gen (s)
1.0      TmaxIC        max time for ic gen (s)
1.0      CdScaleIC     factor by which to scale drag coefficients (-)
0.01     threshIC      threshold for IC convergence (-)
------------------------- need this line --------------------------------------
"""

SPAN = """\
MoorDyn input file for a single line between two fixed points in a light fluid
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
cable  0.0281  1.628  3e+07  -0.5  0  1  1.0  0.0  0.0
---------------------- POINT PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed  0.0  0.0  -100  0  0  0  0
2  Fixed  300  0.0  -100  0  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  cable  1  2  301.5  20  -
---------------------- OPTIONS -----------------------------------------
0      writeLog      Write a log file
0.001  dtM           time step to use in the line integration (s)
9.81   g             gravity (m/s^2)
1.2    WtrDnsty      fluid density (kg/m^3)
1000   WtrDpth       depth of the flat bottom (m)
0      ICgenDynamic  stationary initial-condition solver
1      disableOutput
1      disableOutTime
------------------------- need this line --------------------------------------
"""

SPRING = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input for a simple spring with a mass hanging.
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
main  1.1283791670955126e-08  1e-16  1.0  0  0  0.0  0.0  0.0  0.0
---------------------- POINT PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed  0  0  0   0  0  0  0
2  Free   0  0  -1  1  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  main  1  2  1.0  1  -
---------------------- OPTIONS -----------------------------------------
2           writeLog   Write a log file
1e-3        dtM        time step to use in mooring integration (s)
Midpoint25  tScheme    The time integration Scheme (-)
1.0         WtrDnsty   water density (kg/m^3)
500         WtrDpth    water depth (m)
1.0         dtIC       time interval for analyzing convergence during IC gen (s)
0.0         TmaxIC     max time for ic gen (s)
1.0         CdScaleIC  factor by which to scale drag coefficients (-)
0.01        threshIC   threshold for IC convergence (-)
------------------------- need this line --------------------------------------
"""

WAVEKIN_CURRENT_1 = WD0050_CHAIN.replace(
    "0.5     FrictionCoefficient  general bottom friction coefficient, as a start (-)\n",
    "0.5     FrictionCoefficient  general bottom friction coefficient, as a start (-)\n"
    "1       WaveKin              the wave kinematics are provided through the API (-)\n"
).replace("1  chain  1  2  410  82  -", "1  chain  1  2  410  82  pUD")

# ------------------------------------------------------------------ MoorPy's decks
MOORPY_SAMPLE = """\
MoorDyn v2 Input File
Sample for input to MoorPy
---------------------- LINE TYPES --------------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain  0.2160  286.56  1.23e9  -1.00  0.00  1.00  1.00  0.00  0.00
--------------------- ROD TYPES -----------------------------------------------------
TypeName Diam Mass/m Cd Ca CdEnd CaEnd
(name) (m) (kg/m) (-) (-) (-) (-)
----------------------- BODIES ------------------------------------------------------
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1  coupled  0.00  0.00  -0.75  0.00  0.00  0.00  1.0e6  0.00  0.00  1.0e3  0.00  0.00
---------------------- RODS ---------------------------------------------------------
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
---------------------- POINTS -------------------------------------------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed  800.00    1385.64   -600.00  0.00  0.00  0.00  0.00
2  Body1  10.00     17.32     -21.00   0.00  0.00  0.00  0.00
3  Fixed  -1600.00  0.00      -600.00  0.00  0.00  0.00  0.00
4  Body1  -20.00    0.00      -21.00   0.00  0.00  0.00  0.00
5  Fixed  800.00    -1385.64  -600.00  0.00  0.00  0.00  0.00
6  Body1  10.00     -17.32    -21.00   0.00  0.00  0.00  0.00
---------------------- LINES --------------------------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  chain  1  2  1800.000  40  p
2  chain  3  4  1800.000  40  p
3  chain  5  6  1800.000  40  p
---------------------- OPTIONS ------------------------------------------------------
600.0  depth
--------------------- need this line ------------------------------------------------"""

MOORPY_CASE1 = """\
MoorDyn Input File
single catenary line
----------------------- LINE TYPES ------------------------------------------
Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx
(-) (m) (kg/m) (N) (N-s/-) (-) (-) (-) (-) (-)
main  0.2  500.00  2.0E+09  -1  0  1  0.27  1  0.20
---------------------- POINTS --------------------------------
Node Type X Y Z M V CdA CA
(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed    -800.0  0.0  -300.0  0  0  0  0
2  Coupled  0.0     0.0  0.0     0  0  0  0
---------------------- LINES --------------------------------------
Line LineType NodeAnch NodeFair UnstrLen NumSegs Flags/Outputs
(-) (-) (-) (-) (m) (-) (-)
1  main  1  2  900.00  40  pt
---------------------- SOLVER OPTIONS ---------------------------------------
300    WtrDpth
0.001  dtM        - time step to use in mooring integration (s)
3.0e6  kbot       - bottom stiffness (Pa/m)
3.0e5  cbot       - bottom damping (Pa-s/m)
1.0    dtIC       - time interval for analyzing convergence during IC gen (s)
50.0   TmaxIC     - max time for ic gen (s)
4.0    CdScaleIC  - factor by which to scale drag coefficients (-)
0.001  threshIC   - threshold for IC convergence (-)
------------------------ OUTPUTS --------------------------------------------
FairTen1
AnchTen1
Con1fx
Con1fy
Con1fz
Con2fx
Con2fy
Con2fz
------------------------- need this line --------------------------------------

"""

MOORPY_CASE3 = """\
MoorDyn Input File
single catenary line from VolturnUS-S
----------------------- LINE TYPES ------------------------------------------
Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx
(-) (m) (kg/m) (N) (N-s/-) (-) (-) (-) (-) (-)
main  0.2  500.00  2.0E+09  -1  0  1  0.27  1  0.20
---------------------- POINTS --------------------------------
Node Type X Y Z M V CdA CA
(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed    -800.0  0.0  -300.0  0    0    0  0
2  Free     -400.0  0.0  -100.0  0    200  0  0
3  Free     -200.0  0.0  -100.0  1e5  0    0  0
4  Coupled  0.0     0.0  0.0     0    0    0  0
---------------------- LINES --------------------------------------
Line LineType NodeAnch NodeFair UnstrLen NumSegs Flags/Outputs
(-) (-) (-) (-) (m) (-) (-)
1  main  1  2  400.00  20  pt
2  main  2  3  250.00  10  pt
3  main  3  4  250.00  10  pt
---------------------- SOLVER OPTIONS ---------------------------------------
2      writeLog
300    WtrDpth
0.001  dtM        - time step to use in mooring integration (s)
3.0e6  kbot       - bottom stiffness (Pa/m)
3.0e5  cbot       - bottom damping (Pa-s/m)
1.0    dtIC       - time interval for analyzing convergence during IC gen (s)
0.0    TmaxIC     - max time for ic gen (s)
4.0    CdScaleIC  - factor by which to scale drag coefficients (-)
0.001  threshIC   - threshold for IC convergence (-)
------------------------ OUTPUTS --------------------------------------------
FairTen1
AnchTen1
------------------------- need this line --------------------------------------
"""

MOORPY_VOLTURN_CHAIN = """\
--------------------- MoorDyn Input File ------------------------------------
MoorDyn input file
----------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain  3.33000e-01  6.85000e+02  3.27000e+09  -1.00000e+00  0  1.11000e+00  8.20000e-01  2.00000e-01  2.70000e-01
---------------------- POINT PROPERTIES --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Vessel  -5.80000e+01  0.00000e+00  -1.40000e+01  0.00000e+00  0.00000e+00  0.00000e+00  0.00000e+00
2  Fixed   -8.37600e+02  0.00000e+00  -2.00000e+02  0.00000e+00  0.00000e+00  0.00000e+00  0.00000e+00
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  chain  2  1  8.50000e+02  50  -
---------------------- OPTIONS -----------------------------------------
2      writeLog   Write a log file
0.001  dtM        time step to use in mooring integration (s)
3.0e6  kBot       bottom stiffness (Pa/m)
3.0e5  cBot       bottom damping (Pa-s/m)
1025.0 WtrDnsty   water density (kg/m^3)
200.0  WtrDpth    water depth (m)
1.0    dtIC       time interval for analyzing convergence during IC gen (s)
60.0   TmaxIC     max time for ic gen (s)
4.0    CdScaleIC  factor by which to scale drag coefficients (-)
0.001  threshIC   threshold for IC convergence (-)
------------------------ OUTPUTS --------------------------------------------
FAIRTEN1
POINT1PX
LINE1N50T
END
------------------------- need this line --------------------------------------"""

MOORPY_SEMITAUT = """\
MoorDyn v2 Input File
Generated by MoorPy
---------------------- LINE TYPES --------------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
0  0.2791  480.93  2.058e+09  -1.000e+00  0.000e+00  1.200  1.000  0.20  0.00
1  0.1438  22.42  1.424e+08|1.586e+08  4E9|11e6  0.000e+00  1.200  1.000  0.20  0.00
--------------------- ROD TYPES -----------------------------------------------------
TypeName Diam Mass/m Cd Ca CdEnd CaEnd
(name) (m) (kg/m) (-) (-) (-) (-)
----------------------- BODIES ------------------------------------------------------
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
---------------------- RODS ---------------------------------------------------------
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
---------------------- POINTS -------------------------------------------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed    350.00   606.22   -200.00  0.00  0.00  0.00  0.00
2  Coupled  29.00    50.23    -14.00   0.00  0.00  0.00  0.00
3  Fixed    -700.00  0.00     -200.00  0.00  0.00  0.00  0.00
4  Coupled  -58.00   0.00     -14.00   0.00  0.00  0.00  0.00
5  Fixed    350.00   -606.22  -200.00  0.00  0.00  0.00  0.00
6  Coupled  29.00    -50.23   -14.00   0.00  0.00  0.00  0.00
---------------------- LINES --------------------------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  0  1  2  700.000  26  p
2  0  3  4  700.000  26  p
3  0  5  6  700.000  26  p
---------------------- OPTIONS ------------------------------------------------------
0.001      dtM
3000000.0  kb
300000.0   cb
60         TmaxIC
9.81       g
200        depth
1025       rho
----------------------- OUTPUTS -----------------------------------------------------
FairTen1
FairTen2
END
--------------------- need this line ------------------------------------------------
"""

MOORPY_CASE7A = """\
MoorDyn Input File
Case 7: Single catenary line attached to body to test 6DOF stifness
----------------------- LINE TYPES ------------------------------------------
Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx
(-) (m) (kg/m) (N) (N-s/-) (-) (-) (-) (-) (-)
main  0.2  200.00  2.0E+09  -1  0  4  0.27  4  0.20
----------------------- BODIES ------------------------------------------------------
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1  coupled  0.00  0.00  0.00  0.00  0.00  0.00  0.0  0.0  0.000e+00  0.0  0.00  0.00
---------------------- POINTS --------------------------------
Node Type X Y Z M V CdA CA
(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed  100.0  0.0  -50.0  0  0  0  0
2  Body1  0.0    0.0  -10.0  0  0  0  0
---------------------- LINES --------------------------------------
Line LineType EndA EndB UnstrLen NumSegs Flags/Outputs
(-) (-) (-) (-) (m) (-) (-)
1  main  1  2  112.00  80  pt
---------------------- SOLVER OPTIONS ---------------------------------------
50      WtrDpth
0.0002  dtM        - time step to use in mooring integration (s)
3.0e6   kbot       - bottom stiffness (Pa/m)
3.0e5   cbot       - bottom damping (Pa-s/m)
1.0     dtIC       - time interval for analyzing convergence during IC gen (s)
60.0    TmaxIC     - max time for ic gen (s)
4.0     CdScaleIC  - factor by which to scale drag coefficients (-)
0.001   threshIC   - threshold for IC convergence (-)
------------------------ OUTPUTS --------------------------------------------
FairTen1
Body1fx
------------------------- need this line --------------------------------------
"""

# name: (deck text, current_profile.txt or None, the deck line the refusal names (a
# regex of it) and the words it must hold; None for a deck that imports)
REFUSED = {
    "MoorDyn lines.txt (OC3-Hywind, three lines)": (
        LINES_OC3, r"^3  Fixed", "third fixed or coupled end"),
    "MoorDyn WD0050_Chain.txt (a chain)": (
        WD0050_CHAIN, r"^chain ", "EI: must be > 0"),
    "MoorDyn riser/riser.txt (body and rods)": (
        RISER, r"^1  Free  452", "BODIES: a body"),
    "MoorDyn lowe_and_langley_2006/line.txt (waves through the API)": (
        LOWE_LANGLEY, r"WaveKin", "option WaveKin = 1: waves"),
    "MoorDyn BeamSimplySupported.txt (in air)": (
        BEAM_SIMPLY_SUPPORTED, r"^2  Fixed", "above the still water surface"),
    "MoorDyn BeamCantilevered.txt (a rod)": (
        BEAM_CANTILEVERED, r"^1  cantilever", "RODS: a rod"),
    "MoorDyn polyester/visco.txt (viscoelastic EA)": (
        VISCO, r"^Polyester_290mm", "viscoelastic (static|dynamic) stiffness"),
    "MoorDyn pendulum.txt (a clump weight on a cable)": (
        PENDULUM, r"^main ", "EI: must be > 0"),
    "MoorDyn seafloor.txt (a seafloor file)": (
        SEAFLOOR, r"SeafloorFile", "seafloor file (bathymetry)"),
    "MoorDyn fpe/span.txt (a cable)": (
        SPAN, r"^cable ", "EI: must be > 0"),
    "MoorDyn stability/spring.txt (a hanging mass on a cable)": (
        SPRING, r"^main ", "EI: must be > 0"),
    "MoorDyn wavekin_current_1.txt (waves through the API)": (
        WAVEKIN_CURRENT_1, r"WaveKin", "option WaveKin = 1: waves"),
    "MoorPy examples/sample.txt (a body)": (
        MOORPY_SAMPLE, r"^1  coupled", "BODIES: a body"),
    "MoorPy tests/case1.dat (a chain)": (
        MOORPY_CASE1, r"^main ", "EI: must be > 0"),
    "MoorPy tests/case3.dat (a float on a cable)": (
        MOORPY_CASE3, r"^main ", "EI: must be > 0"),
    "MoorPy tests/case7a.dat (a body)": (
        MOORPY_CASE7A, r"^1  coupled", "BODIES: a body"),
    "MoorPy examples/volturn_chain.dat (a chain)": (
        MOORPY_VOLTURN_CHAIN, r"^chain ", "EI: must be > 0"),
    "MoorPy examples/MoordynSemiTautUpd_simple.dat (three lines)": (
        MOORPY_SEMITAUT, r"^3  Fixed", "third fixed or coupled end"),
}


def _line_of(text: str, pattern: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if re.search(pattern, line))


def _run(text, tmp_path, profile=None, name="deck.dat", out=None):
    """import-moordyn of ``text``: (exit code, stdout, stderr, the scene file)."""
    path = tmp_path / name
    path.write_text(text)
    if profile is not None:
        (tmp_path / "current_profile.txt").write_text(profile)
    out = out or tmp_path / "scene.toml"
    rc = main(["import-moordyn", str(path), "--out", str(out)])
    return rc, out


def _refused(text, tmp_path, capsys, pattern, words, profile=None):
    rc, out = _run(text, tmp_path, profile)
    err = capsys.readouterr().err.strip()
    assert rc == 2 and not out.exists()
    assert len(err.splitlines()) == 1 and err.startswith("error: "), err
    assert words in err, err
    if pattern is not None:
        assert f"deck.dat: line {_line_of(text, pattern)}: " in err, err
    return err


@pytest.mark.parametrize("case", list(REFUSED))
def test_fixture_deck_is_refused_naming_the_line_and_the_feature(case, tmp_path, capsys):
    text, pattern, words = REFUSED[case]
    err = _refused(text, tmp_path, capsys, pattern, words)
    # every header these decks use is a v2 header to MoorDyn-C (SOLVER OPTIONS, POINT and
    # CONNECTION PROPERTIES, LINE DICTIONARY), and "need this line" ends the OPTIONS
    assert "v1" not in err and "unknown section" not in err and "no key" not in err


def test_viv_riser_imports_with_its_current(tmp_path, capsys):
    """MoorDyn viv/viv.txt, a catenary riser in a uniform current: every number of the
    scene from the deck (g: MoorDyn-C's default; the density from WtrDnsty)."""
    rc, out = _run(VIV, tmp_path, VIV_CURRENT)
    notes = capsys.readouterr().out
    assert rc == 0, notes
    s = load_scene(out)
    assert s.name == "deck" and s.gravity == 9.80665 and s.water_density == 1000.0
    assert s.water_depth == 10.0
    lt = s.line_types["cable"]
    assert (lt.outer_diameter, lt.mass_per_length, lt.axial_stiffness, lt.bending_stiffness,
            lt.drag_normal, lt.added_mass, lt.drag_tangential) == (
        0.024, 0.69, 6.66e5, 10.5, 1.2, 2.0, 0.08)
    assert [seg.length for seg in s.segments] == [23.71]
    # anchor on the seabed (Z = -10 = -WtrDpth), hang-off 21.0425 m away at Z = -1
    assert s.ends.anchor == (0.0, 0.0) and s.ends.hang_off == (21.0425, 9.0)
    k = 1.5e5 * 0.024
    m_a = 2.0 * 1000.0 * math.pi / 4.0 * 0.024 ** 2
    assert s.seabed.stiffness == pytest.approx(k, rel=1e-12)
    assert s.seabed.damping == pytest.approx(1e4 * 0.024 / (2 * math.sqrt(k * (0.69 + m_a))),
                                             rel=1e-12)
    assert s.seabed.friction == 0.5
    # 0.2 m/s along +X, the direction from the anchor to the hang-off: heading 0
    assert s.current.heading_deg == 0.0
    assert all(u == pytest.approx(0.2, abs=1e-15) for u in s.current.speeds)
    # the profile's five rows below the seabed (Z < -10) become its value at the seabed
    assert s.current.heights[0] == 0.0 and len(s.current.heights) == 46
    assert "current_profile.txt: 5 row(s) below the seabed" in notes
    assert "VIV lift Cl = 0.7 dropped" in notes
    assert "1/FricDamp = 5e-05 m/s (deck line" in notes
    assert f"Water density 1000 kg/m3 from option WtrDnsty (deck line {_line_of(VIV, 'WtrDnsty')})" \
        in notes


def test_lowe_langley_jumper_without_waves_imports(tmp_path, capsys):
    """MoorDyn's Lowe and Langley jumper without its WaveKin row: density and gravity from
    the deck (WtrDnsty 1000, g 9.807), the coupled end at its deck position, the options
    of MoorDyn's numerics listed as not carried, Echo (v1) skipped as MoorDyn-C skips it."""
    rc, out = _run(LOWE_LANGLEY_STILL, tmp_path)
    notes = capsys.readouterr().out
    assert rc == 0, notes
    s = load_scene(out)
    assert (s.gravity, s.water_density, s.water_depth) == (9.807, 1000.0, 100.0)
    assert s.ends.anchor == (0.0, 45.0) and s.ends.hang_off == (100.0, 95.0)
    assert s.segments[0].length == 170.0
    lt = s.line_types["main"]
    assert (lt.outer_diameter, lt.mass_per_length, lt.axial_stiffness,
            lt.bending_stiffness) == (0.396, 165.0, 500.0e6, 120.8e3)
    assert s.seabed.stiffness == pytest.approx(3.0e6 * 0.396, rel=1e-12)
    text = out.read_text()
    assert "# water_density 1000 kg/m3 (deck line" in text and "gravity 9.807 m/s2 (deck" in text
    for name in ("dtM", "tScheme", "CdScaleIC", "TmaxIC", "dtIC", "threshIC", "ICgenDynamic",
                 "disableOutTime", "writeLog"):
        no = _line_of(LOWE_LANGLEY_STILL, rf"\s{name}\b")
        assert f"{name} (line {no})" in notes
    assert "Option Echo = True (deck line 2)" not in notes      # front matter, not an option


# ------------------------------------------------------------------- options, defaults
GOOD = export_scene(resolve("scr-steel"), segment_length=100.0).text


def _without(text: str, key: str) -> str:
    return re.sub(rf"(?m)^\S+\s+{key}\b.*\n", "", text)


def _with_option(text: str, row: str) -> str:
    return text.replace("---------------------- OUTPUTS", f"{row}\n---------------------- OUTPUTS")


def test_gravity_default_is_moordyn_c(tmp_path, capsys):
    """No g: MoorDyn-C's 9.80665 m/s2 (not 9.81), said in the file and on the terminal."""
    rc, out = _run(_without(GOOD, "g"), tmp_path)
    notes = capsys.readouterr().out
    assert rc == 0 and load_scene(out).gravity == 9.80665
    assert "Gravity 9.80665 m/s2 (MoorDyn-C's default" in notes
    assert "gravity 9.80665 m/s2 (MoorDyn-C's default)" in out.read_text()


@pytest.mark.parametrize("row, density", [
    ("1000 WtrDnsty", 1000.0),      # MoorDyn's and MoorPy's decks
    ("1010 wtrdnsty", 1010.0),      # names in any case
    ("1020 Rho", 1020.0),
    ("1000 rhoW", 1025.0),          # MoorDyn-F's name: MoorDyn-C keeps its 1025
])
def test_density_as_moordyn_c_reads_it(row, density, tmp_path, capsys):
    text = _with_option(_without(GOOD, "rho"), row)
    rc, out = _run(text, tmp_path)
    notes = capsys.readouterr().out
    assert rc == 0 and load_scene(out).water_density == density
    no = _line_of(text, rf"^{row}$")
    comment = next(c for c in out.read_text().splitlines() if c.startswith("# water_density"))
    if density == 1025.0:
        assert f"Option rhoW = 1000 (deck line {no}), MoorDyn-F's water density, is not one " \
            "MoorDyn-C 2.7 reads" in notes
        assert "(MoorDyn-C's default)" in comment
    else:
        assert f"(deck line {no})" in comment


def test_last_option_row_wins(tmp_path, capsys):
    """g, then gravity: MoorDyn-C takes the last row of a name and its aliases."""
    text = _with_option(GOOD, "9.5 gravity")
    rc, out = _run(text, tmp_path)
    notes = capsys.readouterr().out
    assert rc == 0 and load_scene(out).gravity == 9.5
    assert f"Option g is given 2 times (deck lines {_line_of(text, r'^9.81 ')}, " \
        f"{_line_of(text, '^9.5 gravity')}): MoorDyn-C takes the last, gravity = 9.5" in notes


def test_water_depth_from_the_deepest_point(tmp_path, capsys):
    """No WtrDpth: MoorDyn-C's 0 lowered to the deepest point (the anchor, Z = -1000); a
    WtrDpth above a point is lowered too."""
    rc, out = _run(_without(GOOD, "WtrDpth"), tmp_path)
    assert rc == 0 and load_scene(out).water_depth == 1000.0
    assert "The deck gives no WtrDpth" in capsys.readouterr().out
    text = GOOD.replace("1000.0                   WtrDpth", "900.0                   WtrDpth")
    rc, out = _run(text, tmp_path)
    notes = capsys.readouterr().out
    assert rc == 0 and load_scene(out).water_depth == 1000.0
    assert f"WtrDpth = 900 m (deck line {_line_of(text, r'^900.0 +WtrDpth')}) is above " \
        "point 1" in notes


def test_unknown_option_is_skipped_as_moordyn_c_skips_it(tmp_path, capsys):
    text = _with_option(GOOD, "1.0 dtICC")
    rc, out = _run(text, tmp_path)
    assert rc == 0 and out.exists()
    assert f"Option dtICC = 1.0 (deck line {_line_of(text, 'dtICC')}) is not one MoorDyn-C " \
        "2.7 reads" in capsys.readouterr().out


@pytest.mark.parametrize("row, words", [
    ("2 Currents", "option Currents = 2: only 1"),
    ("1.5 StatDynFricScale", "StatDynFricScale = 1.5: a static friction"),
    ("abc kBot", "option kBot: 'abc' is not a number"),
])
def test_options_that_change_the_physics_are_refused(row, words, tmp_path, capsys):
    text = _with_option(GOOD.replace("0.0                      cBot",
                                     "0.0 cBot\n0.3 FrictionCoefficient"), row)
    _refused(text, tmp_path, capsys, rf"^{re.escape(row)}$", words)


# ------------------------------------------------------------------ headers, terminators
@pytest.mark.parametrize("edit", [
    lambda t: t.replace("-- OPTIONS --", "-- SOLVER OPTIONS --"),
    lambda t: t.replace("-- LINE TYPES --", "-- LINE DICTIONARY --"),
    lambda t: t.replace("-- POINTS --", "-- CONNECTION PROPERTIES --"),
    lambda t: t.replace("-- POINTS --", "-- Node Properties --"),
    lambda t: t.replace("-- LINES --", "-- line properties --"),
    # OPTIONS closed by the terminator, no OUTPUTS
    lambda t: re.sub(r"-+ OUTPUTS -+\nAnchTen1\nFairTen1\n", "", t),
    # OPTIONS to the end of the file, no terminator (MoorDyn-C 2.7 reads it)
    lambda t: t[:t.index("---------------------- OUTPUTS")],
    # OUTPUTS to the end of the file
    lambda t: t[:t.index("------------------------- need this line")],
], ids=["solver-options", "line-dictionary", "connection-properties", "node-properties",
        "line-properties", "options-then-terminator", "options-at-eof", "outputs-at-eof"])
def test_header_and_terminator_variants_import_the_same_scene(edit, tmp_path, capsys):
    text = edit(GOOD)
    assert text != GOOD
    rc, out = _run(text, tmp_path)
    assert rc == 0, capsys.readouterr().err
    (tmp_path / "ref").mkdir()
    rc, ref = _run(GOOD, tmp_path / "ref")
    a, b = load_scene(out), load_scene(ref)
    assert (a.gravity, a.water_density, a.water_depth, a.ends, a.seabed) == (
        b.gravity, b.water_density, b.water_depth, b.ends, b.seabed)
    assert a.line_types == b.line_types and a.segments == b.segments


def test_rows_after_a_terminator_are_refused(tmp_path, capsys):
    """Dashes in an option's description end MoorDyn's OPTIONS there: MoorDyn-C reads
    neither the rows after it nor the density below (it keeps 1025): refused."""
    text = re.sub(r"(?m)^1025.0 +rho.*$", "1025.0 rho --- density\n1000.0 g", GOOD)
    err = _refused(text, tmp_path, capsys, r"^1000.0 g$", "holds '---' and so ends the OPTIONS")
    assert f"a row after line {_line_of(text, 'rho ---')}" in err


# ------------------------------------------------------------------ --out, comma numbers
@pytest.mark.parametrize("out", ["my_scene.toml", "sub folder/My Scene.TOML", "new/dir/"])
def test_out_takes_any_file_name_in_any_folder(out, tmp_path, capsys):
    """The scene is named after the deck (riser-deck.dat -> riser-deck), whatever the file."""
    target = tmp_path / out
    rc = main(["import-moordyn", str(_write(tmp_path, "Riser_Deck.dat", GOOD)), "--out",
               str(target) + ("/" if out.endswith("/") else "")])
    assert rc == 0, capsys.readouterr().err
    written = target / "Riser_Deck.toml" if out.endswith("/") else target
    assert load_scene(written).name == "riser-deck"
    assert f"wrote {written}" in capsys.readouterr().out


def test_out_that_cannot_be_written_is_one_line(tmp_path, capsys):
    """--out the deck itself, or below a file: one line naming --out, exit 2, the deck
    kept as it was."""
    deck = _write(tmp_path, "deck.dat", GOOD)
    assert main(["import-moordyn", str(deck), "--out", str(deck)]) == 2
    assert main(["import-moordyn", str(deck), "--out", str(deck / "x.toml")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all(e.startswith("error: command line: --out: ") for e in err)
    assert "is the deck itself" in err[0] and deck.read_text() == GOOD


def _write(folder, name, text):
    (folder / name).write_text(text)
    return folder / name


@pytest.mark.parametrize("edit, pattern, what", [
    (lambda t: t.replace("2275643614.7313323", "2,2756436147313323e9"), r"^steel ",
     "line type 'steel': EA: '2,2756436147313323e9'"),
    (lambda t: t.replace("2  Fixed  1500", "2  Fixed  1500,5"), r"^2  Fixed", "point 2: X"),
    (lambda t: t.replace("1025.0                   rho", "1025,5 rho"), r"^1025,5 rho",
     "option rho: '1025,5'"),
])
def test_comma_decimal_is_refused_as_such(edit, pattern, what, tmp_path, capsys):
    """1,5e9 is 1 to MoorDyn-C's atof: refused as a number with a comma, not read as a
    nonlinear stiffness or a missing position."""
    err = _refused(edit(GOOD), tmp_path, capsys, pattern, what)
    assert "a number with a comma" in err and "nonlinear" not in err
    if "EA" in what:
        assert "MoorDyn-C would take 2" in err and "it is 2.2756436147313323e9" in err


@pytest.mark.parametrize("token", ["1e999", "-1e999", "inf", "nan"])
def test_point_coordinate_that_is_not_finite_is_refused(token, tmp_path, capsys):
    """A point at 1e999 (infinite to both C's atof and Python) is no position: refused with
    the point and column named, not carried into the scene (found by the deck fuzzer, which
    ended in 'cannot write inf to a scene file')."""
    _refused(GOOD.replace("2  Fixed  1500", f"2  Fixed  {token}"), tmp_path, capsys,
             r"^2  Fixed", "point 2: X: must be finite")


def test_misspelt_physics_option_is_refused(tmp_path, capsys):
    """'WaterDepth' is no option of MoorDyn-C (it would go on without it, taking the depth
    of the deepest point): close to WtrDpth, refused as a misspelling."""
    row = "1000.0 WaterDepth"
    _refused(_with_option(_without(GOOD, "WtrDpth"), row), tmp_path, capsys,
             rf"^{row}$", "looks like a misspelt WtrDpth")


def test_sections_out_of_order_are_read_with_a_note(tmp_path, capsys):
    """OUTPUTS before OPTIONS: MoorDyn-C 2.7 finds each section anywhere (measured: the
    options after OUTPUTS are applied), so the scene is the same; a note says so."""
    i, j = GOOD.index("---------------------- OPTIONS"), GOOD.index("---------------------- OUTPUTS")
    k = GOOD.index("------------------------- need this line")
    text = GOOD[:i] + GOOD[j:k] + GOOD[i:j] + GOOD[k:]
    rc, out = _run(text, tmp_path)
    notes = capsys.readouterr().out
    assert rc == 0 and load_scene(out).water_depth == 1000.0 and load_scene(out).gravity == 9.81
    assert f"Section OPTIONS (line {_line_of(text, '-- OPTIONS --')}) comes after OUTPUTS" in notes


def test_free_point_with_a_steady_force_is_refused(tmp_path, capsys):
    """A 12-column point row (MoorDyn-C reads FX FY FZ before CdA Ca): a point load on a
    joint is refused, and its CdA is not taken from the FX column."""
    text = GOOD.replace("2  Fixed  1500", "3  Fixed  1500").replace(
        "1  Fixed  0  0  -1000  0  0  0  0",
        "1  Fixed  0  0  -1000  0  0  0  0\n2  Free  700  0  -500  0  0  0  0  1000  0  0").replace(
        "1  steel  1  2  2000  20  -", "1  steel  1  2  1000  10  -\n2  steel  2  3  1000  10  -")
    _refused(text, tmp_path, capsys, r"^2  Free", "steady force FX FY FZ (a point load)")
