// A genus-3 part for tessera's polycube table and surface pictures (docs/surface.md): an ellipsoid
// with three parallel round through-holes. Modelled in OpenSCAD for tessera; CC0 (public domain).
// Export: openscad -o three_holes.off three_holes.scad   (2,976 triangles, closed, genus 3)
difference() {
    scale([2.2, 1, 1]) sphere(r = 25, $fn = 48);
    for (x = [-28, 0, 28]) translate([x, 0, 0]) cylinder(h = 60, r = 7, center = true, $fn = 32);
}
