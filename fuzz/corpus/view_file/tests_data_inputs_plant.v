/* A view file with every kind of command the readers know.
   The preprocessor runs first: these comments and the #define vanish. */
#define LEAF_SCALE 1.5
#define SIDES 12

projection: perspective
view: 0 dir: 0 0 -1 up: 0 1 0 pan: 0.5 1 0 fov: 30 shift: 2 scale: 0.8   // the main view
box: 0 -1 1 0 5 -2 2
front distance: -10
back distance: 10

z buffer: on
render mode: shaded
shadow map: size: 2048 color: 0.1 0.2 0.3 offset: 2 4
light: V: 1 1 1 D: 0.5 0.5 0.5
light: O: 0 10 0 P: 0 -1 0 2 45 T: 1 0.1 0.01
antialiasing: 4

line style: cylinder
contour sides: SIDES
wireframe line width: 2.5
corrected rotation: off
auto normals: on

tropism: T: 0 -1 0 A: 10 I: 2 E: 0.1 S: 0.05
torque: T: 1 0 0 E: 0.3
stropism: 0 1 0, 0.25

surface: leaf.s LEAF_SCALE 6 4
surface: surfaces/petal.s
texture: bark.png
mesh: cone.obj S: 2 C: 0 1 0
winfont: "Times New Roman" 14 bi
PS linecap: 1
angle increment: 30
no such command: 1
