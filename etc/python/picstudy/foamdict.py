"""OpenFOAM dictionaries read with the place of every entry in the text, so that one entry
can be rewritten and every other character of the file (comments, layout) stays as it was.

Covers what case files use: `keyword value;`, sub-dictionaries `name { ... }`, lists in
parentheses (nested, of dictionaries too), "strings", `//` and `/* */` comments, units in
brackets, `#include`-like directives and `$macro` entries (kept, not expanded).
"""
from .errors import InputError, choices

PUNCTUATION = '{}();'


class Token:
    __slots__ = ('text', 'start', 'end', 'line', 'quoted')

    def __init__(self, text, start, end, line, quoted=False):
        self.text, self.start, self.end, self.line, self.quoted = text, start, end, line, quoted


def tokenize(text, path):
    tokens, i, line, n = [], 0, 1, len(text)
    while i < n:
        c = text[i]
        if c == '\n':
            line += 1
            i += 1
        elif c.isspace():
            i += 1
        elif text.startswith('//', i):
            while i < n and text[i] != '\n':
                i += 1
        elif text.startswith('/*', i):
            close = text.find('*/', i + 2)
            if close < 0:
                raise InputError(path, line, 'comment /* not closed')
            line += text.count('\n', i, close)
            i = close + 2
        elif c == '"':
            j, start_line = i + 1, line
            while j < n and text[j] != '"':
                j += 2 if text[j] == '\\' else 1
            if j >= n:
                raise InputError(path, start_line, 'string not closed')
            line += text.count('\n', i, j)
            tokens.append(Token(text[i + 1:j].replace('\\"', '"'), i, j + 1, start_line, quoted=True))
            i = j + 1
        elif c in PUNCTUATION:
            tokens.append(Token(c, i, i + 1, line))
            i += 1
        elif c == '[':
            # units after a number, e.g. `rho 2650 [kg/m^3];`: not part of the value
            close = text.find(']', i)
            i = n if close < 0 else close + 1
        else:
            j = i
            while j < n and not text[j].isspace() and text[j] not in PUNCTUATION + '"' \
                    and not text.startswith('//', j) and not text.startswith('/*', j):
                j += 1
            tokens.append(Token(text[i:j], i, j, line))
            i = j
    return tokens


def number(word):
    """The int or float a word spells, else None."""
    try:
        return int(word)
    except ValueError:
        pass
    try:
        return float(word)
    except ValueError:
        return None


class Entry:
    """One `keyword value;` or `keyword { ... }` with the span of its value in the text."""

    def __init__(self, keyword, line, parent):
        self.keyword, self.line, self.parent = keyword, line, parent
        self.tokens = []        # a value's tokens (without the ';')
        self.dict = None        # a sub-dictionary's entries
        self.start = self.end = None

    @property
    def path(self):
        return (self.parent.name + '/' if self.parent.name else '') + self.keyword

    def is_dict(self):
        return self.dict is not None

    def value(self):
        """The value as Python: a number, a word or string, a (nested) list; a value of
        several items (`seed 1 2;`) as the list of them; None for an empty one."""
        items, k = [], 0
        while k < len(self.tokens):
            item, k = parse_value(self.tokens, k)
            items.append(item)
        return items[0] if len(items) == 1 else (items or None)

    def words(self):
        return [t.text for t in self.tokens]

    def source(self):
        """The value as written in the file (a quoted string without its quotes)."""
        if len(self.tokens) == 1 and self.tokens[0].quoted:
            return self.tokens[0].text
        return self.parent.text[self.start:self.end]


def parse_value(tokens, k):
    """(value, next index) of the value starting at tokens[k]."""
    t = tokens[k]
    if t.text == '(' and not t.quoted:
        items, k = [], k + 1
        while k < len(tokens) and not (tokens[k].text == ')' and not tokens[k].quoted):
            item, k = parse_value(tokens, k)
            items.append(item)
        return items, k + 1
    if t.quoted:
        return t.text, k + 1
    value = number(t.text)
    return (t.text if value is None else value), k + 1


class Dictionary:
    """Entries by keyword, in order; `name` is the keyword path from the file's top."""

    def __init__(self, name, path, line=0, text=''):
        self.name, self.path, self.line, self.text = name, path, line, text
        self.entries = []

    def find(self, keyword):
        """The entry, the last one when a keyword is given twice (the later wins)."""
        for entry in reversed(self.entries):
            if entry.keyword == keyword:
                return entry
        return None

    def keywords(self):
        seen = []
        for entry in self.entries:
            if entry.keyword not in seen and not entry.keyword.startswith(('#', '$')):
                seen.append(entry.keyword)
        return seen

    def lookup(self, keyword_path):
        """The entry at 'a/b/c' or None."""
        node, entry = self, None
        for part in keyword_path.split('/'):
            if node is None:
                return None
            entry = node.find(part)
            if entry is None:
                return None
            node = entry.dict
        return entry

    def fail(self, keyword, message):
        entry = self.find(keyword)
        line = entry.line if entry else self.line
        where = self.name or self.path
        raise InputError(self.path, line, "keyword '%s' in dictionary %s: %s" % (keyword, where, message))

    # Typed reading for studyDict: each error names the file, line and keyword.
    def get(self, keyword, default=None, required=True):
        entry = self.find(keyword)
        if entry is None:
            if not required:
                return default
            raise InputError(self.path, self.line, "keyword '%s' is undefined in dictionary %s"
                             % (keyword, self.name or self.path))
        if entry.is_dict():
            self.fail(keyword, 'a sub-dictionary where a value is expected')
        return entry.value()

    def optional(self, keyword, default=None):
        return self.get(keyword, default, required=False)

    def get_number(self, keyword, default=None, required=True, condition=None, text=''):
        value = self.get(keyword, default, required)
        if value is default and self.find(keyword) is None:
            return value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(keyword, "'%s' is not a number" % (value,))
        if condition and not condition(value):
            self.fail(keyword, '%s is not allowed; it needs %s' % (value, text))
        return value

    def get_word(self, keyword, valid, default=None):
        value = self.get(keyword, default, required=default is None)
        if value not in valid:
            self.fail(keyword, "'%s' is not a valid choice; valid choices: %s" % (value, choices(valid)))
        return value

    def sub(self, keyword, required=True):
        entry = self.find(keyword)
        if entry is None:
            if required:
                raise InputError(self.path, self.line, "sub-dictionary '%s' is undefined in dictionary %s"
                                 % (keyword, self.name or self.path))
            return None
        if not entry.is_dict():
            self.fail(keyword, 'a value where a sub-dictionary { ... } is expected')
        return entry.dict


def parse(text, path):
    """The file's top dictionary."""
    tokens = tokenize(text, path)
    top = Dictionary('', path, 1, text)
    k = _parse_entries(tokens, 0, top, path, closing=None)
    if k != len(tokens):
        raise InputError(path, tokens[k].line, "unexpected '%s'" % tokens[k].text)
    return top


def read_text(path, label=None):
    """The text of a case file, UTF-8 (a leading byte-order mark dropped). A byte that is not
    UTF-8 (a Latin-1 comment) or a NUL (a binary file) is an InputError at its line, not a
    traceback."""
    label = label or path
    with open(path, 'rb') as f:
        data = f.read()
    nul = data.find(b'\0')
    if nul >= 0:
        raise InputError(label, data.count(b'\n', 0, nul) + 1,
                         'a NUL byte: not a text file (a binary file in place of the dictionary?)')
    try:
        return data.decode('utf-8-sig')
    except UnicodeDecodeError as e:
        raise InputError(label, data.count(b'\n', 0, e.start) + 1,
                         'byte 0x%02x is not UTF-8 text (a Latin-1 or Windows character?): save the file as UTF-8'
                         % data[e.start]) from None


def read(path, label=None):
    return parse(read_text(path, label), label or path)


def _parse_entries(tokens, k, into, path, closing):
    while k < len(tokens):
        t = tokens[k]
        if t.text == closing and not t.quoted:
            return k
        if t.text in PUNCTUATION and not t.quoted:
            raise InputError(path, t.line, "unexpected '%s' where a keyword is expected" % t.text)
        entry = Entry(t.text, t.line, into)
        into.entries.append(entry)
        k += 1
        if t.text.startswith('#'):
            # a directive: `#include "file"` takes one argument, `#inputMode merge` too
            if k < len(tokens) and tokens[k].text not in PUNCTUATION:
                entry.tokens = [tokens[k]]
                k += 1
            continue
        if k < len(tokens) and tokens[k].text == '{' and not tokens[k].quoted:
            entry.dict = Dictionary(entry.path, path, t.line, into.text)
            entry.start = tokens[k].start
            k = _parse_entries(tokens, k + 1, entry.dict, path, closing='}')
            if k >= len(tokens):
                raise InputError(path, t.line, "sub-dictionary '%s' not closed with }" % t.text)
            entry.end = tokens[k].end
            k += 1
            continue
        depth, first = 0, k
        while k < len(tokens):
            s = tokens[k]
            if not s.quoted:
                if s.text in '({':
                    depth += 1
                elif s.text in ')}':
                    depth -= 1
                    if depth < 0:
                        raise InputError(path, s.line, "keyword '%s': unbalanced '%s'" % (t.text, s.text))
                elif s.text == ';' and depth == 0:
                    break
            k += 1
        if k >= len(tokens):
            raise InputError(path, t.line, "keyword '%s': value not ended with ;" % t.text)
        entry.tokens = tokens[first:k]
        if entry.tokens:
            entry.start, entry.end = entry.tokens[0].start, entry.tokens[-1].end
        else:
            entry.start = entry.end = tokens[k].start
        k += 1
    return k


def replace_values(text, path, changes):
    """text with the values at the keyword paths of `changes` {path: new value text}
    replaced; every other character kept."""
    top = parse(text, path)
    spans = []
    for keyword_path, value in changes.items():
        entry = top.lookup(keyword_path)
        if entry is None or entry.is_dict():
            raise KeyError(keyword_path)
        spans.append((entry.start, entry.end, value))
    for start, end, value in sorted(spans, reverse=True):
        text = text[:start] + value + text[end:]
    return text


def value_paths(top):
    """Every keyword path of a value entry, for an error's valid choices."""
    out = []

    def walk(d):
        for e in d.entries:
            if e.keyword.startswith(('#', '$')) or e.keyword == 'FoamFile':
                continue
            if e.is_dict():
                walk(e.dict)
            elif e.path not in out:
                out.append(e.path)
    walk(top)
    return out
