// A flat plate with three round through-holes: a genus-3 CAD part for tessera's polycube tests and
// table (tests/data/surface/openscad_plate_three_holes.off). Modelled in OpenSCAD for tessera; CC0.
// Its flat faces are triangulated between their boundary loops only (no interior vertex), as
// OpenSCAD exports them. Export: openscad -o plate_three_holes.off plate_three_holes.scad
$fn = 40;
difference() {
    hull() for (x = [-24, 24], y = [-8, 8]) translate([x, y, 0]) cylinder(h = 12, r = 6, center = true);
    for (x = [-20, 0, 20]) translate([x, 0, 0]) cylinder(h = 14, r = 6, center = true);
}
