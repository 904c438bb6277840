"""A LAMMPS restart in mid-contact with dc/cmd_tangential + dc/cmd_twisting
(the oblique impacts of oblique_impact: a sliding, spinning sphere pair
and a sphere on a wall): write_restart after 1800 steps, read_restart and
1200 more steps equal, every column of every step exactly, the same deck
run on with a second run command (the law's history of the pair and of
the wall, force and twist, survives the restart), exact profile and
turning points; the restart read on 2 ranks and the whole run on 2 ranks
equal 1 rank. One run of 3000 steps differs from two runs at the second
run's set-up (measured): there LAMMPS computes the forces without
changing the history and the law, as the LIGGGHTS wrapper does, steps
once more on a copy of it."""
import engines

work, _, c = engines.start()
COLS = "time x1 z1 vx1 vz1 wx1 wy1 wz1 fx1 fy1 fz1 x3 z3 vx3 vz3 wx3 wy3 fx3 fz3".split()
DECK = "tangential_restart/in.lammps"
for mem, name in ((0, "profile"), (1, "turningPoints")):
    dw, _ = engines.run("lammps", DECK, work, variables={"phase": "whole", "memory": mem}, tag="whole_" + name)
    d, _ = engines.run("lammps", DECK, work, variables={"phase": "first", "memory": mem}, tag="restart_" + name)
    engines.run("lammps", DECK, work, variables={"phase": "second", "memory": mem}, tag="restart_" + name)
    whole = engines.table(dw + "/out.txt")
    parts = engines.table(d + "/out.txt") + engines.table(d + "/out2.txt")
    engines.compare(c, parts, whole, "%s: write_restart at 1800 steps, read_restart, 1200 steps against the run "
                    "without restart" % name, tol=0.0, names=COLS)
    # in mid-contact at the restart: both contacts' forces act then
    mid = whole[1800]
    c.true(abs(mid[COLS.index("fy1")]) > 0 and abs(mid[COLS.index("fx3")]) > 0,
           "%s: both contacts act at the restart (fy1 %.3g, fx3 %.3g)"
           % (name, mid[COLS.index("fy1")], mid[COLS.index("fx3")]))
    if mem == 1:
        engines.run("lammps", DECK, work, variables={"phase": "second", "memory": mem}, ranks=2,
                    tag="restart_" + name)
        parts2 = engines.table(d + "/out.txt") + engines.table(d + "/out2.txt")
        engines.compare(c, parts2, whole, "%s: the restart read on 2 ranks against 1 rank without restart" % name,
                        tol=0.0, names=COLS)
        d2, _ = engines.run("lammps", DECK, work, variables={"phase": "whole", "memory": mem}, ranks=2,
                            tag="whole2_" + name)
        engines.compare(c, engines.table(d2 + "/out.txt"), whole, "%s: 2 ranks against 1" % name, tol=0.0,
                        names=COLS)
        ds, _ = engines.run("lammps", DECK, work, variables={"phase": "single", "memory": mem}, tag="single_" + name)
        single = engines.table(ds + "/out.txt")
        # the whole run prints the second run's set-up row twice (time 0.00018)
        whole1 = whole[:1801] + whole[1802:]
        k = COLS.index("vx3")
        diff = max(abs(a[k] - b[k]) for a, b in zip(whole1, single)) / max(abs(b[k]) for b in single)
        c.true(len(whole1) == len(single) and diff < 1e-3,
               "%s: two runs against one run of 3000 steps: vx3 differs by %.3g of its largest value (the "
               "second run's set-up)" % (name, diff))
c.finish()
