#!/usr/bin/env python3
"""The keywords of the case files, kept in one place: each registered model's header.

A model's header (the file that declares its class) carries its keyword table in a comment,
the source `picToC -keywords TYPE` prints:

    // | keyword | meaning | units | default |
    // | phi     | friction angle | deg | required, [0, 90) |

Its commands (python3, standard library only):

    keywordTables.py header SOURCE_DIR OUT.H   write the tables as C++ for picToC (the build)
    keywordTables.py check SOURCE_DIR          the drift test (CTest keywordDrift)
    keywordTables.py markdown SOURCE_DIR TYPE  the guide's copy of TYPE's table
    keywordTables.py types SOURCE_DIR          the registered types

`check` fails, one line per finding, when
  - a keyword the code reads (a string literal given to a Dictionary getter, or to one of
    the readers of READERS) is in no keyword table of doc/userGuide,
  - a keyword of a guide table is read nowhere in the code,
  - a guide table row gives no default (nor says `required`),
  - a registered type has no table in its header (or a note that it reads no keywords), or
    the guide's table for it disagrees with the header's (keywords, units, defaults),
  - a registered type is named nowhere in the guide, or a guide table is for a type that
    no model registers.
"""
import os
import re
import sys

LIBRARIES = ("libpic", "libmaterials", "libcontact", "applications")
GETTERS = ("get", "getOrDefault", "getChecked", "getWord", "getWordOrDefault", "subDict",
           "subDictPtr", "found", "isDict", "filePath", "lineOf", "findEntry", "fail")
# Readers that take the keyword as an argument and hand it to the getters (a literal given to
# them is a keyword read).
READERS = ("read", "readVector",                 # TimeFunction: a number, expression or table
           "VectorField",                        # a vector or expressions of x, y, z
           "open",                               # Plugins::open(dict, "libs")
           "select",                             # Registry::select(word, dict, ..., "keyword")
           "bodyId", "bodyIds", "setOpening",    # stages and function objects: body names
           "property", "givenAs",                # mohrCoulomb: a constant or its table
           "coefficient", "nonNegative",         # cosseratDruckerPrager, druckerPrager
           "readStrain", "readFinite", "readStress", "holder", "optionalChecked",
           "HardeningTable")
# Keywords the code builds at run time or reads outside the getters and readers above.
BUILT = {
    # the `tableKey` of mohrCoulomb's property(): keyword + "Table"
    "phiTable", "psiTable", "cTable", "sigmaTTable",
    # the sides of constant/grid and of a stage's `openings`, looped over by name (gridSideNames)
    "left", "right", "bottom", "top", "back", "front",
    # the stage end conditions of `until`, looped over by name (EndCondition.C kindNames)
    "endTime", "duration", "displacement", "equilibrium",
    # picMaterialTest's `general` path: "eps" or "sigma" and a component (LoadPath.C readGeneral)
    "eps11", "eps22", "eps12", "eps23", "eps13",
    "sigma11", "sigma22", "sigma33", "sigma12", "sigma23", "sigma13",
    # the header every dictionary file may have (Dictionary::headerKeyword)
    "FoamFile",
}
# What the code writes (under <time>/uniform/, a decomposition's cellDecomposition) and reads
# back: not case keywords.
STATE = {"stage", "index", "begun", "progress", "clock", "startStep",  # uniform/stage
         "top", "removed", "band",                                       # excavate's progress
         "lastTime", "lastRemoved", "lastMass", "work",                  # functionObjects' state
         "removedMass",                                                  # uniform/time
         "handle", "reference", "travel", "last", "volume", "layers",     # toolFill, toolWear, excavate
         "owner"}                                    # processor<N>/constant/cellDecomposition (picDecompose)
# Kinds chosen by the scene itself, never by a keyword of a case file.
INTERNAL_KINDS = {"gridCoupling"}
# The guide pages whose keyword tables are checked.
GUIDE = "doc/userGuide"

LITERAL = r'"([A-Za-z_][A-Za-z0-9_]*)"'
CALL = re.compile(r'\b(' + "|".join(GETTERS + READERS) + r')\s*(?:<[^;"()]*?>)?\s*\(' +
                  r'((?:\s*[A-Za-z_][\w.:>()-]*?\s*,)*)\s*' + LITERAL)
# A literal given to a reader after other arguments (Registry::select(..., "transfer")).
LATE = re.compile(r'\bselect\s*\([^;]*?,\s*"([A-Za-z_]\w*)"\s*\)')
REGISTER = re.compile(r'^GPIC_REGISTER(?:_DIMS)?\(\s*(\w+)(?:<\d>)?\s*,\s*(\w+)\s*,\s*"(\w+)"\s*\)', re.M)
KIND = re.compile(r'\bclass\s+(\w+)\b[^;{]*\{(?:(?!\bclass\b).)*?kindName\s*=\s*"(\w+)"', re.S)
NO_KEYWORDS = "// Keywords: none of its own."


def sources(root):
    for library in LIBRARIES:
        for folder, _, files in os.walk(os.path.join(root, library)):
            for name in sorted(files):
                if name.endswith((".C", ".H")):
                    path = os.path.join(folder, name)
                    with open(path, encoding="utf-8") as f:
                        yield os.path.relpath(path, root), f.read()


def code_keywords(root):
    """{keyword: first file that reads it}"""
    found = {}
    for path, text in sources(root):
        if path.startswith("libpic/dictionary/"):
            continue  # the getters themselves
        text = re.sub(r"//[^\n]*", "", text)  # comments quote examples, not reads
        for m in CALL.finditer(text):
            found.setdefault(m.group(3), path)
        for m in LATE.finditer(text):
            found.setdefault(m.group(1), path)
    return found


def split_row(line):
    r"""The cells of a table row; `\|` is a bar inside a cell (markdown's escape)."""
    cells = re.split(r"(?<!\\)\|", line.strip())
    if cells and not cells[0].strip():
        cells = cells[1:]
    if cells and not cells[-1].strip():
        cells = cells[:-1]
    return [c.strip() for c in cells]


def keywords_of(cell):
    """The keywords a first cell names: `E`, `nu` or `K`, `G` (guide); E, nu or K, G (header)."""
    quoted = re.findall(r"`([^`]*)`", cell)
    words = quoted if quoted else re.split(r",|/|\bor\b", cell)
    out = []
    for w in words:
        m = re.match(r"\s*([A-Za-z_][A-Za-z0-9_]*)", w)
        if m:
            out.append(m.group(1))
    return out


def default_ok(header, cell):
    """A default cell gives the default, or says `required`; under a "valid / default"
    header the cell must say which."""
    cell = cell.strip()
    if not cell:
        return False
    return "valid" not in header.lower() or "default" in cell.lower() or "required" in cell.lower()


def norm(cell):
    return " ".join(cell.replace("`", "").split())


class Table:
    def __init__(self, where, header):
        self.where = where          # "file:line"
        self.header = header
        self.rows = []              # (keywords, cells, line)
        self.owner = None           # the type of a model's table
        self.notes = []             # a header table's footnotes: "// (*) ..." lines after it

    def default_column(self):
        for i, h in enumerate(self.header):
            if "default" in h.lower():
                return i
        return None

    def column(self, name):
        for i, h in enumerate(self.header):
            if h.lower() == name:
                return i
        return None

    def by_keyword(self):
        out = {}
        d, u = self.default_column(), self.column("units")
        for keys, cells, _ in self.rows:
            for k in keys:
                out[k] = (norm(cells[u]) if u is not None and u < len(cells) else "",
                          norm(cells[d]) if d is not None and d < len(cells) else "")
        return out


def guide_tables(root):
    tables = []
    folder = os.path.join(root, GUIDE)
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".md"):
            continue
        path = os.path.join(GUIDE, name)
        with open(os.path.join(root, path), encoding="utf-8") as f:
            lines = f.read().split("\n")
        table = None
        for i, line in enumerate(lines):
            if not line.startswith("|"):
                table = None
                continue
            if table is None:
                cells = split_row(line)
                m = re.match(r"^(?:`(\w+)`\s+)?keyword$", cells[0])
                if m and i + 1 < len(lines) and lines[i + 1].startswith("|---"):
                    table = Table(f"{path}:{i + 1}", cells)
                    table.owner = m.group(1)
                    tables.append(table)
                else:
                    table = False  # some other table: skip its rows
                continue
            if table is False or line.startswith("|---"):
                continue
            cells = split_row(line)
            table.rows.append((keywords_of(cells[0]), cells, i + 1))
    return tables


def header_table(text, path, start):
    """The comment table that begins at character `start` of text."""
    lines = text[start:].split("\n")
    table = Table(f"{path}:{text.count(chr(10), 0, start) + 1}", split_row(lines[0][2:]))
    for k, line in enumerate(lines[1:]):
        if not line.startswith("// |"):
            for note in lines[k + 1:]:
                if not re.match(r"^// \(\S+\) ", note):
                    break
                table.notes.append(note[3:].strip())
            break
        cells = split_row(line[2:])
        if not cells[0] and table.rows:  # a continuation line: its cells go on the row above
            above = table.rows[-1][1]
            for i, c in enumerate(cells[:len(above)]):
                if c:
                    above[i] = (above[i] + " " + c).strip()
            continue
        table.rows.append((keywords_of(cells[0]), cells, k))
    return table


def registered_types(root):
    """[(kind, type name, class, file that declares the class)]"""
    kinds, declared, registrations = {}, {}, []
    all_sources = list(sources(root))
    for path, text in all_sources:
        for m in KIND.finditer(text):
            kinds[m.group(1)] = m.group(2)
        for m in re.finditer(r"^(?:template\s*<[^>]*>\s*)?(?:class|struct)\s+(\w+)\b(?:\s+final)?\s*[:{]", text, re.M):
            declared.setdefault(m.group(1), (path, m.start()))
        if path.endswith(".C"):
            for m in REGISTER.finditer(text):
                registrations.append((m.group(1), m.group(3), m.group(2)))
    texts = dict(all_sources)
    out = []
    for base, name, cls in registrations:
        if kinds.get(base, base) in INTERNAL_KINDS:
            continue
        path, at = declared.get(cls, (None, 0))
        out.append((kinds.get(base, base), name, cls, path, texts.get(path, ""), at))
    return out


def model_table(text, path, at):
    """The keyword table of the class declared at `at`: the last comment table (or the
    no-keywords note) before it with no other class declared between them."""
    before = text[:at]
    starts = [m.start() for m in re.finditer(r"^// \| keyword\b.*$", before, re.M)]
    notes = [m.start() for m in re.finditer("^" + re.escape(NO_KEYWORDS), before, re.M)]
    start = max(starts + notes, default=-1)
    if start < 0:
        return None
    between = text[start:at]
    if re.search(r"^(?:template\s*<[^>]*>\s*)?(?:class|struct)\s+\w+\b[^;]*?\{", between, re.M):
        return None
    if start in notes:
        t = Table(f"{path}", ["keyword"])
        return t
    return header_table(text, path, start)


def check(root):
    problems = []
    code = code_keywords(root)
    read = set(code) | BUILT
    tables = guide_tables(root)
    documented = {}
    for t in tables:
        d = t.default_column()
        if d is None:
            problems.append(f"{t.where}: keyword table without a default column")
        for keys, cells, line in t.rows:
            where = f"{t.where.split(':')[0]}:{line}"
            if not keys:
                problems.append(f"{where}: row names no `keyword`")
            if d is not None and (d >= len(cells) or not default_ok(t.header[d], cells[d])):
                problems.append(f"{where}: `{keys[0] if keys else '?'}` has no default (write it, or `required`)")
            for k in keys:
                documented.setdefault(k, where)
                if k not in read:
                    problems.append(f"{where}: keyword `{k}` is documented but read nowhere in the code")
    for k, path in sorted(code.items()):
        if k not in documented and k not in STATE:
            problems.append(f"{path}: keyword '{k}' is read but in no keyword table of {GUIDE}")

    guide_text = ""
    for name in sorted(os.listdir(os.path.join(root, GUIDE))):
        with open(os.path.join(root, GUIDE, name), encoding="utf-8") as f:
            guide_text += f.read()
    owned = {}
    for t in tables:
        if t.owner:
            owned.setdefault(t.owner, []).append(t)
    types = registered_types(root)
    for owner, copies in sorted(owned.items()):
        if owner not in {name for _, name, *rest in types}:
            problems.append(f"{copies[0].where}: a table for type `{owner}`, which no model registers")
    for kind, name, cls, path, text, at in types:
        if path is None:
            problems.append(f"{kind} '{name}': class {cls} not found")
            continue
        table = model_table(text, path, at)
        if table is None:
            problems.append(f"{path}: {kind} '{name}' ({cls}) has no keyword table "
                            f"('// | keyword | meaning | units | default |', or '{NO_KEYWORDS}')")
            continue
        if f"`{name}`" not in guide_text:
            problems.append(f"{path}: {kind} '{name}' is named nowhere in {GUIDE}")
        if not table.rows:
            continue
        if table.default_column() is None or table.column("units") is None:
            problems.append(f"{table.where}: the table of {kind} '{name}' needs the columns keyword, meaning, units, default")
            continue
        mine = table.by_keyword()
        for k, (units, deflt) in mine.items():
            if not default_ok(table.header[table.default_column()], deflt):
                problems.append(f"{table.where}: {kind} '{name}', `{k}` has no default (write it, or `required`)")
        # A name with a table per dimension (toolWear): the guide's table with the same
        # keywords, else the one sharing most.
        copies = sorted(owned.get(name, []), key=lambda g: (set(g.by_keyword()) != set(mine),
                                                            -len(set(g.by_keyword()) & set(mine))))
        if not copies:
            problems.append(f"{table.where}: {kind} '{name}' has no table '| `{name}` keyword | meaning | units | default |' in {GUIDE}")
            continue
        theirs = copies[0].by_keyword()
        for k in sorted(set(mine) | set(theirs)):
            if k not in theirs:
                problems.append(f"{copies[0].where}: {kind} '{name}': `{k}` is in {table.where} but not here")
            elif k not in mine:
                problems.append(f"{copies[0].where}: {kind} '{name}': `{k}` is here but not in {table.where}")
            elif mine[k] != theirs[k]:
                problems.append(f"{copies[0].where}: {kind} '{name}', `{k}`: units, default '{theirs[k][0]}', "
                                f"'{theirs[k][1]}' here, '{mine[k][0]}', '{mine[k][1]}' in {table.where}")
    return problems


def cpp_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def header(root, out):
    rows = []
    for kind, name, cls, path, text, at in registered_types(root):
        table = model_table(text, path, at) if path else None
        if table is None:
            continue
        lines = []
        order = [0, 1, table.column("units"), table.default_column()] if table.rows else []
        for keys, cells, _ in table.rows:
            lines.append([cells[i] if i is not None and i < len(cells) else "" for i in order])
        titles = [table.header[i] for i in order]
        rows.append((kind, name, path, titles, lines, table.notes))
    with open(out + ".tmp", "w", encoding="utf-8") as f:
        f.write("// Written by etc/python/keywordTables.py from the models' headers: do not edit.\n")
        f.write("#pragma once\n#include <vector>\n\nnamespace gpic {\n\n")
        f.write("struct KeywordTable {\n    const char* kind;\n    const char* type;\n    const char* header;\n"
                "    std::vector<const char*> titles;             //- keyword, meaning, units, default (or valid / default)\n"
                "    std::vector<std::vector<const char*>> rows;\n"
                "    std::vector<const char*> notes;              //- footnotes, e.g. \"(*) ...\"\n};\n\n")
        f.write("inline const std::vector<KeywordTable>& keywordTables()\n{\n    static const std::vector<KeywordTable> tables{\n")
        for kind, name, path, head, lines, notes in rows:
            f.write(f"        {{{cpp_string(kind)}, {cpp_string(name)}, {cpp_string(path)}, "
                    f"{{{', '.join(cpp_string(c) for c in head)}}}, {{\n")
            for cells in lines:
                f.write("            {" + ", ".join(cpp_string(c) for c in cells) + "},\n")
            f.write("        }, {" + ", ".join(cpp_string(n) for n in notes) + "}},\n")
        f.write("    };\n    return tables;\n}\n\n} // namespace gpic\n")
    # Only a changed table rebuilds picToC.
    old = open(out, encoding="utf-8").read() if os.path.exists(out) else None
    new = open(out + ".tmp", encoding="utf-8").read()
    if old != new:
        os.replace(out + ".tmp", out)
    else:
        os.remove(out + ".tmp")


def markdown(root, wanted):
    """The guide's copy of a model's table (keywordTables.py markdown SOURCE_DIR TYPE)."""
    for kind, name, cls, path, text, at in registered_types(root):
        table = model_table(text, path, at) if path and name == wanted else None
        if table is None or not table.rows:
            continue
        d, u = table.default_column(), table.column("units")
        print(f"| `{name}` keyword | meaning | units | {table.header[d]} |\n|---|---|---|---|")
        for keys, cells, _ in table.rows:
            first = re.sub(r"\b([A-Za-z_][A-Za-z0-9_]*)\b", r"`\1`", cells[0]).replace("` or `", "` or `")
            first = first.replace("`or`", "or")
            print(f"| {first} | {cells[1]} | {cells[u]} | {cells[d]} |")


def main(argv):
    if len(argv) >= 3 and argv[1] == "types":
        print(" ".join(sorted({name for _, name, *rest in registered_types(argv[2])})))
        return 0
    if len(argv) >= 4 and argv[1] == "markdown":
        markdown(argv[2], argv[3])
        return 0
    if len(argv) >= 3 and argv[1] == "check":
        problems = check(argv[2])
        for p in problems:
            print(p)
        print(f"keywordDrift: {len(problems)} finding(s)" if problems else "keywordDrift: code, headers and guide agree")
        return 1 if problems else 0
    if len(argv) >= 4 and argv[1] == "header":
        header(argv[2], argv[3])
        return 0
    print(__doc__.split("\n\n")[0] + "\nusage: keywordTables.py check SOURCE_DIR | header SOURCE_DIR OUT.H | "
          "markdown SOURCE_DIR TYPE | types SOURCE_DIR")
    return 0 if len(argv) > 1 and argv[1] in ("-help", "--help", "-h") else 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
