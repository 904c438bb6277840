"""A Maugis-Dugdale load-unload loop (maugis_loop/): adhesive spheres
approach from a 15 um gap, are pressed 9 um in and pulled apart beyond
separation. LIGGGHTS jkr_elliptic adhesionLaw maugis (and tabor) against
LAMMPS dc/jkr_elliptic law 2 (3) every step within 1e-10; the Dugdale zone
pulling before touch, the loop's hysteresis, separation at the end; 2
ranks against 1; a bad coefficient."""
import engines

work, _, c = engines.start()
COLS = "time z1 fz1 x2 x3 fx2".split()
R = 1e-3


# z0 1e-5: Tabor parameters 0.39 (wall) and 0.31 (pair), Maugis-Dugdale;
# tabor with z0 7e-7: 5.6 (wall: JKR) and 4.4 (pair: Maugis-Dugdale)
for alaw, law, z0 in [("maugis", 2, 1e-5), ("tabor", 3, 7e-7)]:
    g, l, _ = engines.side_by_side(c, "maugis_loop", work, {"alaw": alaw, "z0": z0}, {"law": law, "z0": z0}, alaw,
        "%s z0 %g: LAMMPS dc/jkr_elliptic law %d against LIGGGHTS jkr_elliptic" % (alaw, z0, law), names=COLS)
    # energy the loop takes from the driver: - sum fz1 dz1 (wall), sum fx2 dx2 (pair)
    lw = -sum(0.5 * (a[2] + b[2]) * (b[1] - a[1]) for a, b in zip(l, l[1:]))
    lp = -sum(0.5 * (a[5] + b[5]) * (b[3] - a[3]) for a, b in zip(l, l[1:]))
    c.true(lw > 0 and lp > 0, "%s: hysteresis, the loop dissipates %.4g J (wall), %.4g J (pair)" % (alaw, lw, lp))
    c.true(l[-1][2] == 0.0 and l[-1][5] == 0.0, "%s: apart at the end" % alaw)
    if alaw == "maugis":
        ahead = [r for r in l[:4000] if r[1] > R and r[2] < 0.0]
        c.true(len(ahead) > 0, "maugis: the zone pulls the wall sphere before touch (%d steps, up to %.3g um ahead)"
               % (len(ahead), 1e6 * (max(r[1] for r in ahead) - R) if ahead else 0.0))

d2, _ = engines.run("lammps", "maugis_loop/in.lammps", work, ranks=2, tag="lammps_2ranks")
d1, _ = engines.run("lammps", "maugis_loop/in.lammps", work, tag="lammps_1rank")
engines.compare(c, engines.out(d2), engines.out(d1), "LAMMPS 2 ranks against 1", tol=0.0, names=COLS)

rc, text = engines.run("lammps", "maugis_loop/in.lammps", work, variables={"z0": 0.0}, tag="bad_z0",
                       expect_error=True)
c.true(rc != 0 and "dc/jkr_elliptic coefficient z0 = 0 is outside (0, inf)" in text,
       "z0 0 with law 2: error naming the sub-model, the coefficient and its range")
c.finish()
