#!/usr/bin/env python3
"""dcadvise.py: which contact physics a LIGGGHTS deck's scene needs.

Reads an ordinary LIGGGHTS deck (materials from `fix property/global`,
particle templates or `set ... shape/diameter/density`, insertion speeds,
gravity, box and insertion regions, time step, the pair and wall model
lines; variables resolved as LIGGGHTS resolves them, `-var NAME VALUE` as
LIGGGHTS takes it) and prints, per contact kind (type pair, type on a
wall) and per physical effect, the measure, the model the scene needs
(the cheapest one within the tolerance), its cost from the project's report
and the deck lines; then warnings where the deck's choice is outside its
range. Every physical figure comes from c_core through `dclaw scene` and
`dclaw shape`; this script only reads the deck and applies the tolerance.
doc/advisor.md explains each measure.

Usage:
  dcadvise.py DECK [-var NAME VALUE ...] [--tol T] [--w W] [--sigma S]
              [--H H] [--z0 Z] [--csv FILE] [--dclaw PATH]
  --tol    the force or restitution change below which a richer law is not
           needed (default 0.05)
  --w, --sigma, --H   work of adhesion [J/m^2], rms roughness [m], hardness
           [Pa] where the deck does not give them (workOfAdhesion,
           surfaceRoughness, hardness); without them the effect is assumed
           absent and the output says so
  --z0     range of the surface forces for the Tabor parameter [m]
           (default 0.4e-9)
  --csv    also write every measure per contact kind to FILE
Exit status 0; 2 with a message naming the deck line for a deck it cannot
read.
"""
import ast
import collections
import csv
import io
import math
import operator
import os
import re
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


class DeckError(Exception):
    pass


# ------------------------------------------------------------ deck reading

_OPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
        ast.Pow: operator.pow, ast.USub: operator.neg, ast.UAdd: operator.pos}
_CMP = {ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le, ast.Gt: operator.gt,
        ast.GtE: operator.ge}
_FUNCS = {"sqrt": math.sqrt, "exp": math.exp, "ln": math.log, "log": math.log10, "abs": abs, "sin": math.sin,
          "cos": math.cos, "tan": math.tan, "asin": math.asin, "acos": math.acos, "atan": math.atan,
          "ceil": math.ceil, "floor": math.floor, "round": round}


# the commands whose values the advisor reads (variables are substituted in these only)
READ = {"include", "atom_style", "region", "create_box", "timestep", "pair_style", "fix", "create_atoms", "set",
        "neigh_modify", "if", "read_data", "read_restart"}


class Deck:
    """The commands of a deck, variables substituted, and what they set."""

    def __init__(self, path, cli_vars):
        self.vars = {}        # name -> (style, [values]) ; equal: expression text
        self.locked = set()   # -var names: the deck's own definition does not replace them
        self.defined = {}     # name -> where the deck defined it
        for name, values in cli_vars:
            self.vars[name] = ("index", values)
            self.locked.add(name)
        self.props = {}       # property name -> (style, values, where)
        self.particles = []   # particle classes: dict(type, radius, shape, blockiness, density, where)
        self.templates = {}   # template id -> atom type
        self.regions = {}     # region id -> (style, args, where)
        self.box = None       # (region id, where)
        self.ntypes = None
        self.gravity = None   # (g, (x, y, z), where)
        self.dt = None        # (dt, where)
        self.inserts = []     # dict(vel, region, where)
        self.created = []     # (type, region, where) of create_atoms
        self.sets = []        # what `set group` lines give the created particles
        self.from_file = None  # a read_data / read_restart line (particles the advisor does not read)
        self.pair = None      # (words, where)
        self.walls = []       # (words, where)
        self.atom_style = "granular"
        self.cdf = (1.0, "LIGGGHTS' default")   # neigh_modify contact_distance_factor
        self.assumed = []     # what the reading had to assume
        self.dir = os.path.dirname(os.path.abspath(path))
        self._read(path)

    # --- lines, continuations, comments, includes
    def _read(self, path, depth=0):
        try:
            text = open(path).read()
        except OSError as e:
            raise DeckError("cannot read deck %s: %s" % (path, e.strerror))
        lines = text.split("\n")
        i = 0
        while i < len(lines):
            start = i
            line = lines[i]
            while line.rstrip().endswith("&") and i + 1 < len(lines):
                i += 1
                line = line.rstrip()[:-1] + " " + lines[i]
            i += 1
            where = "%s:%d" % (os.path.basename(path), start + 1)
            self._command(line, where, depth)

    def _strip_comment(self, line):
        out, quote = [], None
        for ch in line:
            if quote:
                if ch == quote:
                    quote = None
            elif ch in "\"'":
                quote = ch
            elif ch == "#":
                break
            out.append(ch)
        return "".join(out)

    def _substitute(self, line, where):
        def value_of(name):
            if name not in self.vars:
                raise DeckError("%s: variable %s is used but never defined (define it, or give -var %s VALUE)"
                                % (where, name, name))
            return self._format(self.value(name, where))

        def immediate(m):
            return self._format(self.evaluate(m.group(1), where))

        # not inside quotes (LIGGGHTS substitutes those when the command runs)
        parts = re.split(r"(\"[^\"]*\"|'[^']*')", line)
        for k in range(0, len(parts), 2):
            p = re.sub(r"\$\(([^)]*)\)", immediate, parts[k])
            p = re.sub(r"\$\{([A-Za-z0-9_]+)\}", lambda m: value_of(m.group(1)), p)
            parts[k] = re.sub(r"\$([A-Za-z0-9_])", lambda m: value_of(m.group(1)), p)
        return "".join(parts)

    @staticmethod
    def _format(v):
        if isinstance(v, float):
            return repr(v) if v != int(v) or abs(v) >= 1e16 else str(int(v))
        return str(v)

    def value(self, name, where):
        style, vals = self.vars[name]
        if style == "equal":
            return self.evaluate(vals[0], "%s (variable %s, defined at %s)" % (where, name, self.defined.get(name, "-v")))
        return vals[0]

    def evaluate(self, expr, where):
        """An equal-style expression: numbers, + - * / ^, functions, PI, v_name."""
        text = expr.strip().strip("\"'")
        text = re.sub(r"\bv_([A-Za-z0-9_]+)", lambda m: "(%s)" % self._format(self._number(m.group(1), where)), text)
        text = text.replace("^", "**").replace("PI", repr(math.pi))
        try:
            tree = ast.parse(text, mode="eval")
            return float(self._eval(tree.body))
        except (SyntaxError, ValueError, TypeError, ZeroDivisionError, OverflowError) as e:
            raise DeckError("%s: cannot evaluate '%s' (%s)" % (where, expr, e))

    def _number(self, name, where):
        if name not in self.vars:
            raise DeckError("%s: variable %s is used but never defined" % (where, name))
        v = self.value(name, where)
        try:
            return float(v)
        except ValueError:
            raise DeckError("%s: variable %s = '%s' is not a number" % (where, name, v))

    def _eval(self, node):
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            return node.value
        if isinstance(node, ast.BinOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](self._eval(node.left), self._eval(node.right))
        if isinstance(node, ast.UnaryOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](self._eval(node.operand))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _FUNCS:
            return _FUNCS[node.func.id](*[self._eval(a) for a in node.args])
        if isinstance(node, ast.Compare) and len(node.ops) == 1 and type(node.ops[0]) in _CMP:
            return float(_CMP[type(node.ops[0])](self._eval(node.left), self._eval(node.comparators[0])))
        if isinstance(node, ast.BoolOp):
            vals = [bool(self._eval(v)) for v in node.values]
            return float(all(vals) if isinstance(node.op, ast.And) else any(vals))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
            return float(not self._eval(node.operand))
        raise ValueError("unsupported element %s" % ast.dump(node)[:40])

    # --- the commands the advisor reads
    def _command(self, raw, where, depth):
        try:
            self._command_words(raw, where, depth)
        except (ValueError, IndexError) as e:
            raise DeckError("%s: cannot read '%s' (%s)" % (where, raw.strip()[:80], e))

    def _command_words(self, raw, where, depth):
        line = self._strip_comment(raw).strip()
        if not line:
            return
        words0 = line.split()
        if words0[0] == "variable" and len(words0) >= 3:
            # $-references substituted now (outside quotes), an equal-style
            # expression evaluated on use, as LIGGGHTS does
            if words0[1] not in self.locked:
                self._variable(shlex.split(self._substitute(line, where)), where)
            return
        if words0[0] not in READ:
            return   # not read: its variables need no value (thermo keywords, per-atom ones)
        line = self._substitute(line, where)
        try:
            w = shlex.split(line)
        except ValueError as e:
            raise DeckError("%s: %s" % (where, e))
        cmd = w[0]
        if cmd == "if" and len(w) >= 4 and w[2] == "then":
            self._if(w, where, depth)
        elif cmd == "include" and len(w) >= 2:
            path = w[1] if os.path.isabs(w[1]) else os.path.join(self.dir, w[1])
            if depth > 10:
                raise DeckError("%s: include nested too deep" % where)
            self._read(path, depth + 1)
        elif cmd == "atom_style":
            self.atom_style = w[1]
        elif cmd == "region" and len(w) >= 3:
            self.regions[w[1]] = (w[2], w[3:], where)
        elif cmd == "create_box" and len(w) >= 3:
            self.ntypes = int(float(w[1]))
            self.box = (w[2], where)
        elif cmd == "timestep":
            self.dt = (float(w[1]), where)
        elif cmd == "pair_style" and len(w) >= 2 and w[1] == "gran":
            self.pair = (w, where)
        elif cmd == "pair_style" and len(w) >= 2 and w[1] == "granular":
            raise DeckError("%s: a LAMMPS deck (pair_style granular): the advisor reads LIGGGHTS decks (pair_style "
                            "gran); the same laws' LAMMPS sub-models are in doc/lammps.md" % where)
        elif cmd == "fix" and len(w) >= 4:
            self._fix(w, where)
        elif cmd == "create_atoms" and len(w) >= 3:
            self.created.append((int(float(w[1])), w[3] if len(w) > 3 and w[2] == "region" else None, where))
        elif cmd == "set" and len(w) >= 4:
            self._set(w, where)
        elif cmd in ("read_data", "read_restart"):
            self.from_file = "%s (%s)" % (where, cmd)
        elif cmd == "neigh_modify" and "contact_distance_factor" in w:
            k = w.index("contact_distance_factor")
            self.cdf = (float(w[k + 1]), where)

    def _if(self, w, where, depth):
        """if "cond" then "cmd" ... [elif "cond" "cmd" ...] [else "cmd" ...]: the chosen commands"""
        k, chosen = 1, None
        while k < len(w) and chosen is None:
            cond = w[k]
            k += 2 if w[k + 1] in ("then",) else 1
            cmds = []
            while k < len(w) and w[k] not in ("elif", "else"):
                cmds.append(w[k])
                k += 1
            if self._truth(cond, where):
                chosen = cmds
            elif k < len(w) and w[k] == "else":
                chosen = w[k + 1:]
            elif k < len(w) and w[k] == "elif":
                k += 1
        for c in chosen or []:
            self._command(c, where, depth)

    def _truth(self, cond, where):
        text = self._substitute(cond, where).replace("&&", " and ").replace("||", " or ").replace("!=", " != ")
        text = re.sub(r"(?<![=!<>])!(?!=)", " not ", text)
        try:
            return bool(self._eval(ast.parse(text.replace("^", "**"), mode="eval").body))
        except (SyntaxError, ValueError, TypeError, ZeroDivisionError):
            raise DeckError("%s: cannot evaluate the condition '%s'" % (where, cond))

    def _variable(self, w, where):
        name, style = w[1], w[2]
        if name in self.locked:
            return
        self.defined[name] = where
        if style in ("index", "string", "loop", "world", "universe", "uloop"):
            self.vars[name] = ("index", w[3:] or [""])
        elif style == "equal":
            self.vars[name] = ("equal", [" ".join(w[3:])])
        elif style == "delete":
            self.vars.pop(name, None)
        # atom, file, python, ... styles are not values the advisor reads

    def _fix(self, w, where):
        style = w[3]
        if style == "property/global" and len(w) >= 6:
            name, kind = w[4], w[5]
            vals = w[6:]
            if kind == "peratomtypepair":
                vals = vals[1:]   # the leading n
            try:
                self.props[name] = (kind, [float(x) for x in vals], where)
            except ValueError:
                raise DeckError("%s: property %s: values %s are not all numbers" % (where, name, " ".join(vals)))
        elif style in ("particletemplate/sphere", "particletemplate/superquadric"):
            self._template(w, where)
        elif style.startswith("insert/"):
            ins = {"where": where, "vel": (0.0, 0.0, 0.0), "region": None}
            for k, word in enumerate(w):
                if word == "vel" and k + 4 < len(w) and w[k + 1] == "constant":
                    ins["vel"] = tuple(float(x) for x in w[k + 2:k + 5])
                elif word == "region" and k + 1 < len(w):
                    ins["region"] = w[k + 1]
            self.inserts.append(ins)
        elif style == "gravity" and len(w) >= 5:
            g = float(w[4])
            vec = (0.0, 0.0, -1.0)
            if "vector" in w:
                k = w.index("vector")
                vec = tuple(float(x) for x in w[k + 1:k + 4])
            self.gravity = (g, vec, where)
        elif style == "wall/gran":
            self.walls.append((w, where))

    def _template(self, w, where):
        t = {"where": where}
        k = 4
        atom_type = None
        while k < len(w):
            if w[k] == "atom_type":
                atom_type = int(float(w[k + 1]))
                k += 2
            elif w[k] == "density" and w[k + 1] == "constant":
                t["density"] = float(w[k + 2])
                k += 3
            elif w[k] == "radius":
                t["radius"] = self._distribution(w[k + 1:], where, "radius")
                k += 1
            elif w[k] == "shape" and w[k + 1] == "constant":
                t["shape"] = tuple(float(x) for x in w[k + 2:k + 5])
                k += 5
            elif w[k] == "blockiness" and w[k + 1] == "constant":
                t["blockiness"] = tuple(float(x) for x in w[k + 2:k + 4])
                k += 4
            else:
                k += 1
        if atom_type is None:
            raise DeckError("%s: particle template without atom_type" % where)
        self.templates[w[1]] = atom_type
        t["type"] = atom_type
        self.particles.append(t)

    def _distribution(self, w, where, what):
        if w[0] == "constant":
            return float(w[1])
        if w[0] in ("gaussian", "lognormal") and len(w) >= 4:
            mu, sd = float(w[2]), float(w[3])
            self.assumed.append("%s: %s %s: the mean plus 2 standard deviations, %.4g m" % (where, what, w[0], mu + 2 * sd))
            return mu + 2.0 * sd
        if w[0] == "uniform" and len(w) >= 4:
            return max(float(w[2]), float(w[3]))
        raise DeckError("%s: %s distribution '%s' is not one the advisor reads" % (where, what, " ".join(w[:4])))

    def _set(self, w, where):
        # set group G ... type/diameter/shape/blockiness/density
        t = {"where": where}
        k = 3
        while k < len(w):
            if w[k] == "diameter":
                t["radius"] = 0.5 * float(w[k + 1]); k += 2
            elif w[k] == "shape":
                t["shape"] = tuple(float(x) for x in w[k + 1:k + 4]); k += 4
            elif w[k] == "blockiness":
                t["blockiness"] = tuple(float(x) for x in w[k + 1:k + 3]); k += 3
            elif w[k] == "density":
                t["density"] = float(w[k + 1]); k += 2
            else:
                k += 1
        if len(t) > 1:
            self.sets.append(t)


# ------------------------------------------------------------ the scene

def prop(deck, name, i, j=None, required=True, default=None):
    """A per-type or per-type-pair property for types i (and j), 1-based."""
    if name not in deck.props:
        if required:
            raise DeckError("the deck sets no %s (fix ID all property/global %s ...): the advisor needs it" % (name, name))
        return default
    kind, vals, where = deck.props[name]
    try:
        if kind == "peratomtype":
            return vals[i - 1]
        if kind == "peratomtypepair":
            n = int(round(math.sqrt(len(vals))))
            return vals[(i - 1) * n + ((j or i) - 1)]
        if kind == "scalar":
            return vals[0]
    except IndexError:
        raise DeckError("%s: %s has no value for type %d%s" % (where, name, i, "" if j is None else " and %d" % j))
    raise DeckError("%s: %s given as %s, which the advisor does not read" % (where, name, kind))


def region_box(deck, rid):
    if rid not in deck.regions:
        return None
    style, args, where = deck.regions[rid]
    if style == "block" and len(args) >= 6:
        try:
            return [float(x) for x in args[:6]]
        except ValueError:
            return None
    if style == "cylinder" and len(args) >= 6:
        ax, c1, c2, r, lo, hi = args[0], float(args[1]), float(args[2]), float(args[3]), float(args[4]), float(args[5])
        if ax == "z":
            return [c1 - r, c1 + r, c2 - r, c2 + r, lo, hi]
    return None


def scene_of(deck, opts):
    """Types, their particles, the largest impact speed and where each came from."""
    src = {}
    parts = [dict(p) for p in deck.particles]
    if deck.sets:   # `set group` lines give every created type the same values
        for t in sorted({c[0] for c in deck.created} or {1}):
            d = {"type": t}
            for s in deck.sets:
                d.update(s)
            parts.append(d)
    if not parts:
        raise DeckError("the deck defines no particles the advisor can read (particletemplate/sphere, "
                        "particletemplate/superquadric, or create_atoms with set ... diameter/shape)%s"
                        % ("; its particles come from a file at %s" % deck.from_file if deck.from_file else ""))
    for d in parts:
        if "radius" not in d and "shape" not in d:
            raise DeckError("%s: type %d has no radius or shape" % (d.get("where", "deck"), d["type"]))
        if "density" not in d:
            raise DeckError("%s: type %d has no density" % (d.get("where", "deck"), d["type"]))
    # a type with several templates: each its own class, named by its size
    for d in parts:
        same = [e for e in parts if e["type"] == d["type"]]
        size = d["radius"] if "radius" in d else max(d["shape"])
        d["label"] = "type %d" % d["type"] + (" (%s %s m)" % ("radius" if "radius" in d else "semi-axis", fmt(size))
                                             if len(same) > 1 else "")
    g = deck.gravity[0] if deck.gravity else 0.0
    src["g"] = deck.gravity[2] if deck.gravity else "no fix gravity: g = 0"
    # fall height: from the top of the insertion (or creation) regions to the box bottom
    bottom, top = None, None
    if deck.box:
        b = region_box(deck, deck.box[0])
        if b:
            bottom = b[4]
    for ins in deck.inserts:
        b = region_box(deck, ins["region"]) if ins["region"] else None
        if b:
            top = b[5] if top is None else max(top, b[5])
    for (_, rid, _) in deck.created:
        b = region_box(deck, rid) if rid else None
        if b:
            top = b[5] if top is None else max(top, b[5])
    if bottom is None or top is None:
        h = 0.0
        deck.assumed.append("no box and insertion region the advisor can read: fall height 0")
    else:
        h = max(top - bottom, 0.0)
    vin = max([math.sqrt(sum(x * x for x in ins["vel"])) for ins in deck.inserts] or [0.0])
    v = math.sqrt(vin * vin + 2.0 * g * h)
    src["v"] = "insertion speed %.3g m/s (%s) and free fall over %.3g m (box bottom to the top of the insertion or creation region)" % (
        vin, deck.inserts[0]["where"] if deck.inserts else "none", h)
    if v <= 0.0:
        v = 0.01
        deck.assumed.append("no insertion speed and no fall: impact speed 0.01 m/s")
    if not deck.dt:
        raise DeckError("the deck sets no timestep")
    return parts, v, g, src


def shape_of(d):
    """(shape, blockiness) of a superquadric type, None for a sphere."""
    if "shape" in d:
        return d["shape"], d.get("blockiness", (2.0, 2.0))
    return None


def run_dclaw(dclaw, args):
    p = subprocess.run([dclaw] + [str(a) for a in args], capture_output=True, text=True)
    if p.returncode != 0:
        raise DeckError("dclaw %s: %s" % (args[0], p.stderr.strip()))
    rows = list(csv.DictReader(io.StringIO(p.stdout)))
    return {k: float(x) for k, x in rows[0].items()}


def report_costs():
    """Whole-run time over stock hertz + history from the project's report."""
    path = os.path.join(HERE, "..", "doc", "report", "table.csv")
    cost = {}
    try:
        for r in csv.DictReader(open(path)):
            if r["run_ratio"]:
                cost[(r["family"], r["law"])] = float(r["run_ratio"])
    except OSError:
        pass
    pick = {"hertz_elliptic": ("superquadric", "hertz_elliptic (exact)"),
            "gw_rough": ("rough", "tabulated GW law (gw_rough default)"),
            "jkr_elliptic": ("adhesion", "jkr_elliptic (hint carried)"),
            "jkr_elliptic adhesionLaw dmt": ("adhesion", "adhesionLaw dmt (DMT)"),
            "jkr_elliptic adhesionLaw maugis": ("adhesion", "adhesionLaw maugis (Maugis-Dugdale)")}
    pick.update({law.name: law.report for law in TANGENTIAL_LAWS})
    return {m: cost.get(k) for m, k in pick.items()}


def fmt(x):
    return "%.3g" % x


# ------------------------------------------------------------ the contacts

class Scene:
    """What every contact of the deck shares: the particle classes, the
    largest impact speed, gravity, the time step, the tolerance, the costs
    from the report, and the warnings and contact distance factors the
    effects hand on (one list for the whole deck)."""

    def __init__(self, deck, opts):
        self.opts, self.dclaw, self.tol = opts, opts.dclaw, opts.tol
        self.parts, self.v, self.g, self.src = scene_of(deck, opts)
        self.dt, self.dt_where = deck.dt
        self.costs = report_costs()
        self.warnings, self.cdf_need = [], []

    def measure_shapes(self):
        """a superquadric class: its volume-equivalent radius and one-radius force errors, once"""
        for d in self.parts:
            s = shape_of(d)
            if s:
                (sx, sy, sz), (n1, n2) = s
                d["shape_errors"] = run_dclaw(self.dclaw, ["shape", "--a", sx, "--b", sy, "--c", sz, "--n1", n1,
                                                           "--n2", n2])
                d["radius"] = d["shape_errors"]["R_eq"]

    def cost(self, model):
        """the cost column: the report's whole-run ratio of the model"""
        return ("%.2fx" % self.costs[model]) if self.costs.get(model) else "n/a in the report"


def contact_kinds(deck, parts):
    """Every pair of particle classes, then each class on the walls (walls of the last wall/gran line's type)."""
    kinds = [(i, j) for i in range(len(parts)) for j in range(i, len(parts))]
    wall_type = 1
    if deck.walls:
        for words, where in deck.walls:
            if "type" in words:
                wall_type = int(float(words[words.index("type") + 1]))
        kinds += [(i, "wall") for i in range(len(parts))]
    return kinds, wall_type


class Contact:
    """One contact kind: its bodies and materials as the deck gives them,
    and dclaw scene's measures of it (m, one row of the --csv output).
    needs: each effect's verdict so far, for the effects after it (the
    tangential deck line reads whether roughness needs gw_rough)."""

    def __init__(self, deck, s, ia, ib, wall_type):
        opts = s.opts
        self.s = s
        self.tol, self.v, self.dt = s.tol, s.v, s.dt
        da = s.parts[ia]
        self.wall = wall = ib == "wall"
        db = None if wall else s.parts[ib]
        a = da["type"]
        bt = wall_type if wall else db["type"]
        self.reach_R = da["radius"] + (0.0 if wall else db["radius"])   # the radius the contact distance scales
        self.shape_rows = [d["shape_errors"] for d in ([da] if wall else [da, db]) if "shape_errors" in d]
        E1, nu1 = prop(deck, "youngsModulus", a), prop(deck, "poissonsRatio", a)
        E2, nu2 = prop(deck, "youngsModulus", bt), prop(deck, "poissonsRatio", bt)
        self.mu = mu = prop(deck, "coefficientFriction", a, bt, required=False, default=0.0)
        self.w = w = prop(deck, "workOfAdhesion", a, bt, required=False, default=opts.w or 0.0)
        sig_a = prop(deck, "surfaceRoughness", a, required=False, default=None)
        sig_b = prop(deck, "surfaceRoughness", bt, required=False, default=None)
        sigma = math.hypot(sig_a, sig_b) if sig_a is not None and sig_b is not None else (opts.sigma or 0.0)
        self.sigma = sigma
        mu_r = prop(deck, "roughnessMu", a, bt, required=False, default=4.0)
        H = prop(deck, "hardness", a, required=False, default=None)
        if H is not None and prop(deck, "hardness", bt, required=False, default=None) is not None:
            H = min(H, prop(deck, "hardness", bt))
        self.H = H = H if H is not None else (opts.H or 0.0)
        args = ["scene", "--R1", da["radius"], "--R2", 0 if wall else db["radius"], "--E1", E1, "--E2", E2,
                "--nu1", nu1, "--nu2", nu2, "--rho1", da["density"], "--rho2", da["density"] if wall else db["density"],
                "--v", s.v, "--g", s.g, "--dt", s.dt, "--mu", mu, "--w", w, "--z0", opts.z0, "--sigma", sigma,
                "--mu_rough", mu_r, "--H", H]
        self.m = m = run_dclaw(s.dclaw, args)
        m.update({"in_nu": nu1, "in_sigma": sigma, "in_w": w, "in_H": H, "in_mu_rough": mu_r, "in_mu": mu, "in_v": s.v})
        self.kind = "%s on a wall" % da["label"] if wall else "%s with %s" % (da["label"], db["label"])
        m["kind"] = self.kind
        self.needs = {}


# ------------------------------------------------------------ the effects
#
# One function per physical effect, in doc/advisor.md's order ("The
# measures"): each takes a Contact, takes or computes its measure, applies
# its rule and returns its verdict, an Advice (the row printed for the
# contact); warnings and the contact distance factor an advised law needs
# go to the scene (c.s.warnings, c.s.cdf_need). EFFECTS lists them as they
# print: a new effect is one more function and one more entry there (and,
# if the deck's pair_style may lack or pay for its law, one in DECK_CHECKS).

class Advice(collections.namedtuple("Advice", "measure needs cost line")):
    """measure: the figures, for reading; needs: the model the contact
    needs ("-" where not assessed); cost: its cost column; line: the deck
    line for it ("-": none)."""


def not_assessed(measure):
    return Advice(measure, "-", "-", "-")


def effect_time_step(c):
    """the elastic Hertz collision at the largest speed integrated at the deck's dt; LIGGGHTS' Rayleigh limit"""
    m, dt, v, tol = c.m, c.dt, c.v, c.tol
    steps = max(1, int(m["t_c"] / dt))
    hz = run_dclaw(c.s.dclaw, ["classical", "--law", 1, "--damping", 4, "--Estar", m["Estar"], "--R", m["R"],
                               "--meff", m["meff"], "--v0", v, "--steps", steps, "--summary", 1])
    t_err = abs(hz["Tc"] / hz["Tc_closed"] - 1.0)
    e_err = abs(hz["e"] - 1.0)
    m["duration_error"], m["restitution_error"] = t_err, e_err
    ok = m["dt_over_T_rayleigh"] <= 0.2 and max(t_err, e_err) <= tol
    if not ok:
        c.s.warnings.append("%s (%s): dt = %s s is %s Rayleigh times (LIGGGHTS' limit 0.2) and integrates the "
                            "fastest collision in %d steps, its duration off by %s and its elastic restitution by %s "
                            "(tolerance %s)" % (c.kind, c.s.dt_where, fmt(dt), fmt(m["dt_over_T_rayleigh"]), steps,
                                                fmt(t_err), fmt(e_err), fmt(tol)))
    return Advice("dt %s s = %s Rayleigh times; %d steps per collision at %s m/s: duration off by %s, elastic "
                  "restitution by %s" % (fmt(dt), fmt(m["dt_over_T_rayleigh"]), steps, fmt(v), fmt(t_err), fmt(e_err)),
                  "ok" if ok else "smaller dt", "-",
                  "-" if ok else "timestep %s" % fmt(min(0.2 * m["T_rayleigh"], m["t_c"] / 50)))


def effect_hertz_range(c):
    """a/R at the impact's largest overlap against Fessler & Ollerton's 0.5: a warning, no law fixes it"""
    fessler = c.m["fessler"]
    if fessler > 0.5:
        c.s.warnings.append("%s: the impact's contact radius is %s of the particle radius: beyond Hertz's range "
                            "(0.5, Fessler-Ollerton); a softer law does not fix it, a stiffer material or slower "
                            "impact does" % (c.kind, fmt(fessler)))
    return Advice("a/R at impact %s (Fessler-Ollerton: below 0.5)" % fmt(fessler),
                  "ok" if fessler <= 0.5 else "beyond Hertz", "-", "-")


def effect_shape(c):
    """the one-radius Hertz force against elliptic Hertz (dclaw shape's errors of the superquadric classes)"""
    if not c.shape_rows:
        return Advice("spheres: 0", "hertz", "1x", "-")
    err = max(r["err_pair_max" if not c.wall else "err_wall_max"] for r in c.shape_rows)
    rms = max(r["err_pair_rms" if not c.wall else "err_wall_rms"] for r in c.shape_rows)
    c.m["shape_error_max"], c.m["shape_error_rms"] = err, rms
    if err > c.tol:
        return Advice("one-radius force error max %s, rms %s" % (fmt(err), fmt(rms)), "hertz_elliptic",
                      c.s.cost("hertz_elliptic"), "pair_style gran model hertz_elliptic ... surface superquadric")
    return Advice("one-radius force error max %s, rms %s" % (fmt(err), fmt(rms)), "hertz (volume-equivalent radius)",
                  "1x", "-")


def effect_plasticity(c):
    """the restitution of the elastic-plastic impact alone (Jamari-Schipper) against 1"""
    if not c.H > 0:
        return not_assessed("not assessed: no hardness in the deck (give --H)")
    m = c.m
    measure = ("impact over yield speed %s (delta_max/delta_n1 %s); restitution from plasticity alone %s"
               % (fmt(c.v / m["v_yield"]), fmt(m["plastic_ratio"]), fmt(m["e_plastic"])))
    if 1.0 - m["e_plastic"] > c.tol:
        return Advice(measure, "jamari_ep", c.s.cost("jamari_ep"),
                      "model jamari_ep; fix ... property/global hardness peratomtype %s" % fmt(c.H))
    return Advice(measure, "elastic law", "1x", "-")


def adhesion_law(tabor):
    """the adhesive law for a Tabor parameter: (its name in the cost table, the words after `model jkr_elliptic`)"""
    if tabor < 0.1:
        return "jkr_elliptic adhesionLaw dmt", " adhesionLaw dmt"
    if tabor < 5:
        return "jkr_elliptic adhesionLaw maugis", " adhesionLaw maugis"
    return "jkr_elliptic", ""


def effect_adhesion(c):
    """the JKR pull-off against the weight and the impact force, and the sticking speed; the law by Tabor's parameter"""
    if not c.w > 0:
        return not_assessed("not assessed: no workOfAdhesion in the deck (give --w)")
    m, v, tol = c.m, c.v, c.tol
    tab = m["tabor"]
    sticks = v < m["v_stick"]
    measure = ("Tabor %s; JKR pull-off %s N = %s weights, %s of the impact force; sticking speed %s m/s "
               "(impact %s of it: %s)" % (fmt(tab), fmt(m["pulloff"]), fmt(m["pulloff_over_weight"]),
                                          fmt(m["pulloff_over_F_max"]), fmt(m["v_stick"]), fmt(v / m["v_stick"]),
                                          "sticks" if sticks else "rebounds"))
    if not (m["pulloff_over_weight"] > tol or m["pulloff_over_F_max"] > tol or sticks):
        return Advice(measure, "elastic law", "1x", "-")
    law, words = adhesion_law(tab)
    dmt, md = law.endswith("dmt"), law.endswith("maugis")
    need = "jkr_elliptic adhesionLaw maugis (Tabor %s: between JKR and DMT)" % fmt(tab) if md else law
    if not dmt:   # a DMT contact ends at touch: no neck to reach
        c.s.cdf_need.append(1.0 + (m["md_reach"] if md else m["jkr_separation"]) / c.reach_R)
    return Advice(measure, need, c.s.cost(law),
                  "model jkr_elliptic%s; fix ... property/global workOfAdhesion peratomtypepair ...%s"
                  % (words, "; fix ... property/global equilibriumSeparation peratomtypepair ... (z0 %s m)"
                     % fmt(c.s.opts.z0) if md else ""))


def effect_roughness(c):
    """the rough-sphere law (tabulated GW) over Hertz at the overlaps at rest and at impact"""
    if not c.sigma > 0:
        return not_assessed("not assessed: no surfaceRoughness in the deck (give --sigma)")
    m = c.m
    measure = ("sigma/delta %s at rest, %s at impact; rough force / Hertz - 1: %s at rest, %s at impact"
               % (fmt(m["sigma_over_delta_rest"]), fmt(m["sigma_over_delta_max"]), fmt(m["rough_force_rest"]),
                  fmt(m["rough_force_max"])))
    if max(abs(m["rough_force_rest"]), abs(m["rough_force_max"])) > c.tol:
        c.s.cdf_need.append(1.0 + m["rough_reach"] / c.reach_R)
        return Advice(measure, "gw_rough", c.s.cost("gw_rough"),
                      "model gw_rough; fix ... property/global surfaceRoughness peratomtype ...")
    return Advice(measure, "smooth law", "1x", "-")


class TangentialLaw(collections.namedtuple("TangentialLaw", "name line line_rough report error")):
    """A candidate tangential law: name (the needs column, and its key in
    the costs), line (the deck line), line_rough (the deck line where the
    contact needs gw_rough too), report (its (family, law) row in
    doc/report/table.csv: the cost), error (of the contact's measures m: its
    error on the scene's contact, the change of the contact point's
    tangential restitution in the 45-degree impact against cmd_tangential)."""


# The tangential laws the verdict chooses among: the cheapest whose error is
# within the tolerance (cheapest_within). A new law is one more entry, with
# its report row and its error on the contact (a figure dclaw scene gives,
# e.g. its tangential restitution against beta_cmd).
TANGENTIAL_LAWS = [
    TangentialLaw("tangential history", "tangential history", "tangential history",
                  ("tangential", "stock tangential history"), lambda m: abs(m["beta_cmd"] - m["beta_history"])),
    TangentialLaw("cmd_tangential cmdMemory turningPoints", "tangential cmd_tangential cmdMemory turningPoints",
                  "tangential cmd_tangential cmdMemory turningPoints tangentialRoughness on  (the summits' stiffness, "
                  "with gw_rough)", ("tangential", "cmd_tangential cmdMemory turningPoints"),
                  lambda m: abs(m["beta_cmd"] - m["beta_turning_points"])),
    TangentialLaw("cmd_tangential", "tangential cmd_tangential",
                  "tangential cmd_tangential tangentialRoughness on  (the summits' stiffness, with gw_rough)",
                  ("tangential", "cmd_tangential"), lambda m: 0.0),   # the exact law: the reference
]


def cheapest_within(laws, m, tol, costs):
    """The cheapest of the laws (cost from the report; one without a cost
    after those with one; equal costs: the first listed) whose error on the
    contact is within tol; none within: the most accurate."""
    within = [law for law in laws if law.error(m) <= tol]
    if not within:
        return min(laws, key=lambda law: law.error(m))
    return min(within, key=lambda law: costs[law.name] if costs.get(law.name) is not None else math.inf)


def effect_tangential_memory(c):
    """the contact point's tangential restitution of a 45-degree impact under each candidate law"""
    if not c.mu > 0:
        return not_assessed("no friction (coefficientFriction 0 or absent)")
    m = c.m
    law = cheapest_within(TANGENTIAL_LAWS, m, c.tol, c.s.costs)
    return Advice("tangential restitution of a 45-degree impact: %s with spring-sliding, %s with Cattaneo-Mindlin, "
                  "%s with its bounded memory (slip distance %s m, one impact moves %s of them)" % (
                      fmt(m["beta_history"]), fmt(m["beta_cmd"]), fmt(m["beta_turning_points"]),
                      fmt(m["slip_distance"]), fmt(m["slip_ratio"])),
                  law.name, c.s.cost(law.name), law.line_rough if c.needs.get("roughness") == "gw_rough" else law.line)


def effect_rolling(c):
    """how far an impact's contact rolls, against Kalker's hand-over (rollingDistanceMin 2 semi-axes)"""
    if not c.mu > 0:
        return not_assessed("no friction: no creep forces")
    X = c.m["rolled_semi_axes"]
    return Advice("a 45-degree impact rolls its contact %s semi-axes; rolling_friction kalker acts after 2 "
                  "(rollingDistanceMin)%s" % (fmt(X), ": not in impacts; steady rolling over many semi-axes is not "
                                              "assessed" if X < 2 else ""),
                  "no rolling model for impacts" if X < 2 else "rolling_friction kalker where contacts roll", "-", "-")


Effect = collections.namedtuple("Effect", "name advise")
EFFECTS = [Effect("time step", effect_time_step),
           Effect("Hertz range", effect_hertz_range),
           Effect("shape", effect_shape),
           Effect("plasticity", effect_plasticity),
           Effect("adhesion", effect_adhesion),
           Effect("roughness", effect_roughness),
           Effect("tangential memory", effect_tangential_memory),
           Effect("rolling", effect_rolling)]


def check_contact_distance(c, deck, models):
    """models acting apart: the contact distance factor they need (the plugin's set-up refuses less) against the
    deck's"""
    m = c.m
    jkr_gap = max(m["jkr_separation"], m["md_reach"]) if models & {"maugis", "tabor"} else m["jkr_separation"]
    for law, gap, on in (("jkr_elliptic", jkr_gap, c.w > 0), ("gw_rough", m["rough_reach"], c.sigma > 0)):
        need_cdf = 1.0 + gap / c.reach_R
        m["contact_distance_factor_" + law] = need_cdf
        if on and law in models and deck.cdf[0] < need_cdf:
            c.s.warnings.append("%s: %s acts until the surfaces are %s m apart: neigh_modify contact_distance_factor "
                                "%s (%s) is below the %s it needs" % (c.kind, law, fmt(gap), fmt(deck.cdf[0]),
                                                                      deck.cdf[1], fmt(need_cdf)))


# ------------------------------------------------------------ the deck's own models

# Per effect with a richer law: the law, whether the deck's pair_style has it
# (of its model, tangential and cohesion words and cmdMemory setting), which
# of its words the verdict names, whether a deck that has the law without the
# need pays for it (of the particle classes), which advised laws it is (of
# the needs column; default: those that begin with its name) and whether the
# check applies to the deck at all; in the order the verdicts print.
DeckCheck = collections.namedtuple("DeckCheck", "effect model has shown pays needs applies")
DeckCheck.__new__.__defaults__ = (None, None)
DECK_CHECKS = [
    DeckCheck("plasticity", "jamari_ep", lambda h: h["model"] == "jamari_ep", "model", None),
    DeckCheck("adhesion", "jkr_elliptic", lambda h: h["model"] == "jkr_elliptic" or h["cohesion"] not in ("off", "-"),
              "model", None),
    DeckCheck("roughness", "gw_rough", lambda h: h["model"] == "gw_rough", "model", None),
    DeckCheck("tangential memory", "cmd_tangential", lambda h: h["tangential"] == "cmd_tangential", "tangential", None),
    # a deck with cmd_tangential: the exact profile where a contact needs it,
    # the bounded memory (cmdMemory turningPoints) where that is within the tolerance
    DeckCheck("tangential memory", "cmd_tangential's exact profile (cmdMemory profile)",
              lambda h: h["cmdMemory"] != "turningPoints", "cmdMemory", None, lambda n: n == "cmd_tangential",
              lambda h: h["tangential"] == "cmd_tangential"),
    DeckCheck("shape", "hertz_elliptic",
              lambda h: h["model"] in ("hertz_elliptic", "jkr_elliptic", "gw_rough", "jamari_ep"), "model",
              lambda parts: any("shape" in p for p in parts)),   # spheres: the elliptic law costs nothing more
]


def deck_verdicts(deck, rows, parts):
    """a richer law a contact needs that the deck lacks, or one the deck pays for that no assessed contact needs"""
    words = deck.pair[0] if deck.pair else []
    have = {"model": "-", "tangential": "-", "cohesion": "off", "cmdMemory": "profile"}
    for key in have:
        if key in words and words.index(key) + 1 < len(words):
            have[key] = words[words.index(key) + 1]
    verdicts = []
    for chk in DECK_CHECKS:
        if chk.applies and not chk.applies(have):
            continue
        has = chk.has(have)
        needs = chk.needs or (lambda n, m=chk.model: n.startswith(m))
        needed = any(r[1] == chk.effect and needs(r[3]) for r in rows)
        assessed = any(r[1] == chk.effect and r[3] != "-" for r in rows)
        if needed and not has:
            verdicts.append("%s: the contacts need %s; the deck has %s" % (chk.effect, chk.model, have[chk.shown]))
        elif has and assessed and not needed and (chk.pays is None or chk.pays(parts)):
            verdicts.append("%s: the deck pays for %s, which no contact needs within the tolerance" % (chk.effect,
                                                                                                        chk.model))
    return verdicts


# ------------------------------------------------------------ the advice

def advise(deck, opts, out):
    """Every effect for every contact kind; the report on out (and --csv).
    Returns the rows (kind, effect, measure, needs, cost, deck line), each
    contact's measures, the particle classes and the largest impact speed."""
    s = Scene(deck, opts)
    kinds, wall_type = contact_kinds(deck, s.parts)
    s.measure_shapes()
    models = set(deck.pair[0] if deck.pair else []) | {x for words, _ in deck.walls for x in words}
    rows, measures = [], []
    for (ia, ib) in kinds:
        c = Contact(deck, s, ia, ib, wall_type)
        measures.append(c.m)
        for eff in EFFECTS:
            adv = eff.advise(c)
            c.needs[eff.name] = adv.needs
            rows.append((c.kind, eff.name) + tuple(adv))
        check_contact_distance(c, deck, models)
    write_report(out, deck, opts, s, rows, measures)
    if opts.csv:
        write_csv(opts.csv, measures)
    return rows, measures, s.parts, s.v


def write_report(out, deck, opts, s, rows, measures):
    v, parts = s.v, s.parts
    model_line = " ".join(deck.pair[0][2:]) if deck.pair else "(no pair_style gran)"
    out.write("dcadvise: %s\n" % opts.deck)
    out.write("pair model: %s (%s)\n" % (model_line, deck.pair[1] if deck.pair else "-"))
    out.write("scene values:\n")
    out.write("  largest impact speed %s m/s: %s\n" % (fmt(v), s.src["v"]))
    out.write("  gravity %s m/s^2 (%s); time step %s s (%s)\n" % (fmt(s.g), s.src["g"], fmt(s.dt), s.dt_where))
    for d in parts:
        desc = ("superquadric %s blockiness %s" % (" x ".join(fmt(x) for x in d["shape"]),
                " ".join(fmt(x) for x in d.get("blockiness", (2, 2))))) if "shape" in d else "sphere"
        out.write("  %s: %s, radius %s m%s, density %s kg/m^3 (%s)\n" % (
            d["label"], desc, fmt(d["radius"]), " (volume-equivalent)" if "shape" in d else "", fmt(d["density"]),
            d.get("where", "-")))
    for mm in measures:
        out.write("  %s: overlap at rest %s m, at impact %s m; contact radius at impact %s m; collision %s s\n" % (
            mm["kind"], fmt(mm["delta_rest"]), fmt(mm["delta_max"]), fmt(mm["a_max"]), fmt(mm["t_c"])))
    out.write("\nper contact, tolerance %s (the force or restitution change a richer law may make):\n" % fmt(s.tol))
    head = ("effect", "needs", "cost", "measure")
    for kind in [mm["kind"] for mm in measures]:
        sub = [(r[1], r[3], r[4], r[2]) for r in rows if r[0] == kind]
        wd = [max(len(x[k]) for x in sub + [head]) for k in range(3)]
        out.write("\n%s\n" % kind)
        for r in [head] + sub:
            out.write("  " + "  ".join(r[k].ljust(wd[k]) for k in range(3)) + "  " + r[3] + "\n")
    lines = sorted({r[5] for r in rows if r[5] != "-"})
    if s.cdf_need:
        lines.append("neigh_modify contact_distance_factor %.6g  (the largest the advised models need; at least "
                     "LIGGGHTS' 1)" % max(1.0, max(s.cdf_need)))
    if lines:
        out.write("\ndeck lines for what the scene needs:\n")
        for ln in lines:
            out.write("  %s\n" % ln)
    words = deck.pair[0] if deck.pair else []
    verdicts = deck_verdicts(deck, rows, parts)
    out.write("\nthe deck's models (%s): %s\n" % (" ".join(words[2:]) if words else "no pair_style gran",
                                                 "as the contacts need" if not verdicts else ""))
    for vd in verdicts:
        out.write("  - %s\n" % vd)
    if deck.assumed:
        out.write("\nassumed:\n")
        for a in deck.assumed:
            out.write("  - %s\n" % a)
    if s.warnings:
        out.write("\nwarnings:\n")
        for wng in s.warnings:
            out.write("  - %s\n" % wng)


def write_csv(path, measures):
    keys = ["kind"]
    for mm in measures:   # the union, in order: a superquadric class adds its shape errors
        keys += [k for k in mm if k not in keys]
    with open(path, "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=keys)
        wr.writeheader()
        for mm in measures:
            wr.writerow(mm)


class Opts:
    pass


def parse_args(argv):
    o = Opts()
    o.deck, o.tol, o.w, o.sigma, o.H, o.z0, o.csv = None, 0.05, None, None, None, 0.4e-9, None
    o.dclaw = os.environ.get("DCLAW", os.path.join(HERE, "..", "build", "c_core", "dclaw"))
    o.vars = []
    i = 0
    floats = {"--tol": "tol", "--w": "w", "--sigma": "sigma", "--H": "H", "--z0": "z0"}
    while i < len(argv):
        a = argv[i]
        if a in ("-h", "--help"):
            print(__doc__)
            sys.exit(0)
        if a in ("-var", "-v"):
            name = argv[i + 1] if i + 1 < len(argv) else None
            vals = []
            i += 2
            while i < len(argv) and not argv[i].startswith("-"):
                vals.append(argv[i])
                i += 1
            if not name or not vals:
                raise DeckError("-var needs a name and a value")
            o.vars.append((name, vals))
            continue
        if a in floats:
            if i + 1 >= len(argv):
                raise DeckError("%s needs a value" % a)
            try:
                setattr(o, floats[a], float(argv[i + 1]))
            except ValueError:
                raise DeckError("%s: '%s' is not a number" % (a, argv[i + 1]))
            i += 2
            continue
        if a in ("--csv", "--dclaw"):
            setattr(o, a[2:], argv[i + 1])
            i += 2
            continue
        if a.startswith("-"):
            raise DeckError("unknown option %s (dcadvise.py --help)" % a)
        if o.deck:
            raise DeckError("one deck only (got %s and %s)" % (o.deck, a))
        o.deck = a
        i += 1
    if not o.deck:
        raise DeckError("usage: dcadvise.py DECK [-var NAME VALUE ...] [--tol T] [--w W] [--sigma S] [--H H] [--z0 Z] [--csv FILE]")
    if not (o.tol > 0):
        raise DeckError("--tol must be > 0")
    return o


def main(argv):
    try:
        opts = parse_args(argv)
        deck = Deck(opts.deck, opts.vars)
        advise(deck, opts, sys.stdout)
    except DeckError as e:
        sys.stderr.write("dcadvise: %s\n" % e)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
