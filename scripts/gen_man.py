#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""gen_man.py -- the reference pages of both bindings, generated from one source.

Sources, all in the repository:
  include/gks_functions.def      id, symbol, ISO name and allowed operating states of the
                                 functions the table lists (the state error follows from
                                 the states, src/c/core/gks_state.h)
  include/gks.h                  every C entry point (GKS_API): its prototype, and the
                                 comment above it (errors listed there, "Errors: ...")
  tests/core/test_state_errors.c c_<SYM>: the C function of each table row
  bindings/fortran/*.c, *.f      every FORTRAN 77 entry point, its argument list and the
                                 C function it calls
  src/c/core/**/*.c, *.h         the error numbers each C entry point can report, read
                                 from its body and the helpers it calls
  src/c/core/gks_errors.def      the message of each error number
  docs/man/src/*.txt             the hand-written text: per function (group) the meaning
                                 of each argument with its coordinate system, defaults,
                                 notes, examples; names.txt the ISO names the table lacks,
                                 glossary.txt the arguments that mean the same everywhere
  docs/man/gks3d.7.txt           the overview page gks3d(7)

Output (written with --out DIR, default the source tree):
  docs/man/man3/<c name>.3       one page per C entry point (the first function of a text
                                 group carries the page; the others are .so links to it)
  docs/man/man3/<fortran>.3      one .so link per FORTRAN 77 entry point (lower case name)
                                 to the page of the C function it calls
  docs/man/man7/gks3d.7          the overview
  docs/reference/*.md            the same text as Markdown, with an index (README.md)
Options: --check  compare with the files in the tree instead of writing (exit 1 on a
                  difference; the ctest docs_man_current)
         --stats  print the counts (C, Fortran, pages, pages with hand-written text)
"""
import argparse
import collections
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))


def read(path):
    with open(os.path.join(ROOT, path), encoding='utf-8') as f:
        return f.read()


def strip_comments(text):
    """C text with comments replaced by blanks (line structure kept)."""
    def blank(m):
        return re.sub(r'[^\n]', ' ', m.group(0))
    return re.sub(r'/\*.*?\*/|//[^\n]*', blank, text, flags=re.S)


# ------------------------------------------------------------------ the function table
STATE_NAMES = {1: 'GKCL', 2: 'GKOP', 3: 'WSAC', 4: 'SGOP', 5: 'WSAC or SGOP',
               6: 'WSOP or WSAC', 7: 'WSOP, WSAC or SGOP', 8: 'GKOP, WSOP, WSAC or SGOP'}
MASKS = {'GKS_S_GKCL': {'GKCL'}, 'GKS_S_GKOP': {'GKOP'}, 'GKS_S_WSOP': {'WSOP'},
         'GKS_S_WSAC': {'WSAC'}, 'GKS_S_SGOP': {'SGOP'},
         'GKS_S_WSOPEN': {'WSOP', 'WSAC', 'SGOP'},
         'GKS_S_OPEN': {'GKOP', 'WSOP', 'WSAC', 'SGOP'}}
STATE_ERR = {frozenset({'GKCL'}): 1, frozenset({'GKOP'}): 2, frozenset({'WSAC'}): 3,
             frozenset({'SGOP'}): 4, frozenset({'WSAC', 'SGOP'}): 5,
             frozenset({'WSOP', 'WSAC'}): 6, frozenset({'WSOP', 'WSAC', 'SGOP'}): 7,
             frozenset({'GKOP', 'WSOP', 'WSAC', 'SGOP'}): 8}


def mask_error(expr):
    s = set()
    for part in expr.split('|'):
        s |= MASKS[part.strip()]
    return STATE_ERR.get(frozenset(s), 0)


def parse_table():
    rows = {}
    for m in re.finditer(r'^GKS_FN\((\d+),\s*(\w+),\s*"([^"]+)",\s*([^,]+),', read('include/gks_functions.def'), re.M):
        rows[m.group(2)] = {'id': int(m.group(1)), 'sym': m.group(2), 'iso': m.group(3),
                            'state_err': mask_error(m.group(4))}
    return rows


def table_c_names():
    """SYM -> C name: the first g...( call of c_SYM in the state-error test."""
    text = strip_comments(read('tests/core/test_state_errors.c'))
    out = {}
    for m in re.finditer(r'static void c_([A-Z0-9_]+)\(void\)', text):
        body = text[m.end():]
        c = re.search(r'(?<![a-z0-9_])(g[a-z][a-z0-9_]*)\(', body)
        if c:
            out[m.group(1)] = c.group(1)
    return out


def errors_def():
    return {int(m.group(1)): m.group(2) for m in
            re.finditer(r'^GKS_ERR\((\d+),\s*"((?:[^"\\]|\\.)*)"\)', read('src/c/core/gks_errors.def'), re.M)}


# ------------------------------------------------------------------ the C binding
def parse_c_header():
    """[(name, prototype, comment)] of every GKS_API function of gks.h, in order."""
    text = read('include/gks.h')
    out = []
    comment = ''
    last_end = 0
    for m in re.finditer(r'GKS_API\s+([^;{]*?)\b(\w+)\s*\(([^;]*?)\)\s*;([ \t]*/\*(.*?)\*/)?', text, re.S):
        if m.group(2) == 'visibility':
            continue
        before = text[last_end:m.start()]
        cm = list(re.finditer(r'/\*(.*?)\*/', before, re.S))
        # the comment directly above (only blank space after it), else the one above a
        # group of declarations (kept from the previous declaration)
        direct = bool(cm and before[cm[-1].end():].strip() == '' and '-----' not in cm[-1].group(1))
        if direct:
            comment = cm[-1].group(1)
        elif cm or '\n\n' in before:
            comment = ''
        ret = ' '.join(m.group(1).split())
        args = ' '.join(m.group(3).split())
        out.append({'name': m.group(2), 'ret': ret, 'args': args,
                    'comment': clean_comment(comment), 'direct': direct,
                    'trail': clean_comment(m.group(5) or '')})
        last_end = m.end()
    return out


def clean_comment(c):
    lines = [re.sub(r'^\s*\*?\s?', '', l) for l in c.split('\n')]
    return ' '.join(' '.join(lines).split())


# ------------------------------------------------------------------ the Fortran binding
FTYPES = {'fint': 'INTEGER', 'freal': 'REAL', 'char': 'CHARACTER*(*)', 'double': 'DOUBLE PRECISION'}


def fortran_params(params):
    """C parameter list of a wrapper -> [(NAME, type, intent)] (hidden lengths dropped)."""
    out = []
    for p in [x.strip() for x in params.split(',') if x.strip()]:
        if p == 'void' or p.startswith('size_t'):
            continue
        m = re.match(r'(const\s+)?(\w+)\s*\*?\s*(\w+)(\[\])?$', p)
        if not m:
            out.append((p.upper(), '?', '?'))
            continue
        ty = FTYPES.get(m.group(2), m.group(2))
        out.append((m.group(3).upper(), ty, 'in' if m.group(1) else 'out'))
    return out


# FORTRAN 77 entry points whose C function the wrapper reaches by another way
F_TO_C = {'GOPKS': 'gopen_gks',     # through gks_open_gks_unit (the error file is a unit)
          'GERHND': 'gerr_hand', 'GERLOG': 'gerr_log',
          'GKEMSG': 'gks_error_message',  # asks INQUIRE ERROR STATE first, for the detail
          # the 2-D forms the wrapper makes through the 3-D function: the 2-D page
          'GFAS': 'gfill_area_set', 'GQASF': 'ginq_asfs', 'GQSGA': 'ginq_seg_attrs'}
# C functions a wrapper calls as helpers, never its own function
HELPERS = {'gcreate_store', 'gdel_store'}


def parse_fortran(c_names):
    """{FNAME: {'args': [...], 'c': C function, 'comment': text}} of every entry point."""
    res = {}
    macros = {}
    for fn in sorted(os.listdir(os.path.join(ROOT, 'bindings/fortran'))):
        path = 'bindings/fortran/' + fn
        if fn.endswith('.f'):
            text = read(path)
            if fn == 'gkunam.f':
                continue  # helper of the binding, not exported
            for m in re.finditer(r'^      SUBROUTINE +(G[A-Z0-9]+)\s*\(([^)]*)\)', text, re.M | re.I):
                up = m.group(1).upper()
                res[up] = {'args': [(a.strip().upper(), 'INTEGER', 'in') for a in m.group(2).split(',')],
                           'c': F_TO_C.get(up), 'comment': '', 'file': path}
            continue
        if not fn.endswith('.c'):
            continue
        raw = read(path)
        text = strip_comments(raw)
        # static helpers of the file: name -> body
        statics = {}
        for m in re.finditer(r'^static\s+[^;{()]*?\b(\w+)\s*\([^;{]*?\)\s*\{', text, re.M):
            statics[m.group(1)] = body_at(text, m.end() - 1)

        def api_names(body, seen):
            """The C API names a body uses (directly, or through the file's static helpers),
            in order of appearance."""
            out = []
            for ident in re.findall(r'[A-Za-z_]\w*', body):
                if ident in c_names and ident not in out:
                    out.append(ident)
                elif ident in statics and ident not in seen:
                    seen.add(ident)
                    out += [x for x in api_names(statics[ident], seen) if x not in out]
            return out

        def pick(names, up):
            if up in F_TO_C:
                return F_TO_C[up]
            own = [n for n in names if n not in HELPERS]
            return own[0] if own else (names[0] if names else None)

        # wrapper-making macros: #define NAME(lower, UPPER, ...) ... FNAME(lower, UPPER)(params) body
        for m in re.finditer(r'#define\s+(\w+)\(lower,\s*UPPER([^)]*)\)((?:.*\\\n)*.*)', text):
            body = m.group(3).replace('\\\n', '\n')
            pm = re.search(r'FNAME\(lower,\s*UPPER\)\s*\(([^)]*)\)', body)
            if pm:
                extra = [a.strip() for a in m.group(2).split(',') if a.strip()]
                macros[m.group(1)] = (fortran_params(pm.group(1)), extra, body)
        # direct definitions
        for m in re.finditer(r'FAPI\s+void\s+FNAME\((\w+),\s*(\w+)\)\s*\(([^)]*)\)\s*\{', text):
            up = m.group(2)
            body = body_at(text, m.end() - 1)
            names = api_names(body, set())
            fc = re.search(r'FNAME\(\w+,\s*(\w+)\)\s*\(', body)
            res[up] = {'args': fortran_params(m.group(3)), 'c': pick(names, up),
                       'fcall': fc.group(1) if fc else None,
                       'comment': comment_before(raw, text, m.start()), 'file': path}
        # macro uses
        for m in re.finditer(r'^(\w+)\((\w+),\s*(\w+)((?:,[^\n]*)?)\)\s*$', text, re.M):
            if m.group(1) not in macros or m.group(2).upper() != m.group(3):
                continue
            params, extra, body = macros[m.group(1)]
            vals = [a.strip() for a in m.group(4).split(',') if a.strip()]
            sub = dict(zip(extra, vals))
            body = re.sub(r'[A-Za-z_]\w*', lambda x: sub.get(x.group(0), x.group(0)), body)
            names = api_names(body, set())
            res[m.group(3)] = {'args': params, 'c': pick(names, m.group(3)),
                               'comment': comment_before(raw, text, m.start()), 'file': path}
    # subset forms that call the full form (GRQSTS -> GRQST): the full form's C function
    for k, v in res.items():
        if not v['c'] and v.get('fcall') in res:
            v['c'] = res[v['fcall']]['c']
    return res


def body_at(text, brace):
    depth = 0
    for i in range(brace, len(text)):
        if text[i] == '{':
            depth += 1
        elif text[i] == '}':
            depth -= 1
            if depth == 0:
                return text[brace:i + 1]
    return text[brace:]


def comment_before(raw, text, pos):
    """The comment ending right before pos (only blank space between), cleaned."""
    before = raw[:pos]
    m = re.search(r'/\*((?:(?!\*/).)*)\*/\s*$', before, re.S)
    return clean_comment(m.group(1)) if m else ''


# ------------------------------------------------------------------ errors from the source
WSC_ERR = {'GKS_WSC_NOT_MO': 31, 'GKS_WSC_NOT_MI': 33, 'GKS_WSC_NOT_INPUT': 35,
           'GKS_WSC_NOT_WISS': 36}
# the core's files whose functions an entry point's errors are read from (the pipeline and
# the stores report through the entry point's own code)
CORE_DIRS = ['src/c/core/api', 'src/c/core']


def call_args(text, pos):
    """The argument text of the call whose '(' is at pos."""
    depth = 0
    for i in range(pos, len(text)):
        if text[i] == '(':
            depth += 1
        elif text[i] == ')':
            depth -= 1
            if depth == 0:
                return text[pos + 1:i]
    return text[pos + 1:]


class SourceErrors:
    """Which error numbers each C entry point can report: the literals its body, and the
    core functions and macros it calls (transitively, function-like macros expanded with
    their arguments), report or store as an error number, and the workstation checks'
    errors by their category flags. State errors come from the table (or the inquiry's
    state mask), not from here: the helpers' state numbers belong to other functions.
    An approximation: a helper shared by several functions contributes all it can report."""

    def __init__(self, known):
        self.known = known
        self.funcs = {}    # name -> body (comments removed), the non-static ones
        self.statics = {}  # (file, name) -> body
        self.file_of = {}  # entry point or non-static function -> its file
        self.macros = {}   # name -> (parameters or None, replacement text)
        self.params = {}   # (file, function) -> its parameter names
        self.consts = {}
        texts = []
        for d in CORE_DIRS:
            for fn in sorted(os.listdir(os.path.join(ROOT, d))):
                if fn.endswith(('.c', '.h')):
                    texts.append((d + '/' + fn, strip_comments(read(d + '/' + fn))))
        for path, text in texts:
            for m in re.finditer(r'#define\s+(\w+)(\(([^)]*)\))?((?:.*\\\n)*.*)', text):
                params = [x.strip() for x in m.group(3).split(',')] if m.group(2) else None
                self.macros.setdefault(m.group(1), (params, m.group(4).replace('\\\n', '\n')))
                v = m.group(4).strip()
                if re.fullmatch(r'\d+', v):
                    self.consts[m.group(1)] = int(v)
            for m in re.finditer(r'^(static\s+)?(?:GKS_API\s+|inline\s+)*[A-Za-z_][\w \t*]*?\b(\w+)\s*\(([^;{]*?)\)\s*\{', text, re.M):
                name = m.group(2)
                if name in ('if', 'while', 'for', 'switch'):
                    continue
                body = body_at(text, m.end() - 1)
                params = [re.sub(r'\[.*', '', q).split()[-1].lstrip('*') if q.split() else ''
                          for q in split_args(m.group(3))]
                if m.group(1) or 'static' in text[m.start():m.end()].split('(')[0].split():
                    self.statics[(path, name)] = body
                    self.params[(path, name)] = params
                elif name not in self.funcs:
                    self.funcs[name] = body
                    self.file_of[name] = path
                    self.params[(path, name)] = params
            # entry points a macro defines: NAME(gxxx, ...) at the start of a line
            for m in re.finditer(r'^(\w+)\((g\w+)\b', text, re.M):
                if m.group(1) in self.macros and m.group(2) not in self.funcs:
                    self.funcs[m.group(2)] = self.expand(m.group(1), call_args(text, m.end() - len(m.group(2)) - 1))
                    self.file_of[m.group(2)] = path

    def lookup(self, path, name):
        """(file, body) of the function name as seen from file path."""
        if (path, name) in self.statics:
            return path, self.statics[(path, name)]
        if name in self.funcs:
            return self.file_of[name], self.funcs[name]
        return None, None

    def expand(self, name, args):
        params, body = self.macros[name]
        if not params:
            return body
        vals = split_args(args)
        sub = dict(zip(params, vals))
        return re.sub(r'[A-Za-z_]\w*', lambda x: sub.get(x.group(0), x.group(0)), body)

    def errors(self, name):
        out = set()
        self._walk_body(self.file_of.get(name), self.funcs.get(name, ''), {name}, out)
        return out

    def _walk_body(self, path, body, seen, out):
        for m in re.finditer(r'gks_ws_checked\s*\(', body):
            args = call_args(body, m.end() - 1)
            out.update({20, 25})
            flags = re.findall(r'GKS_WSC_\w+', args)
            if flags:
                out.update(WSC_ERR[f] for f in flags)
            elif not re.search(r',\s*0\s*$', args):
                out.update(WSC_ERR.values())
        if re.search(r'GKS_INQ_ARGS\b', body):
            out.add(2003)
        for m in re.finditer(r'(?:GKS_FAIL(?:_RET)?|gks_error_report|gks_binding_error)\s*\(\s*(\w+)', body):
            self._lit(m.group(1), out)
        for m in re.finditer(r'(?:\*\s*\w*err\w*|\berr\w*|\be|\brc|\bperr)\s*=\s*([^;=][^;]*);', body):
            for v in re.findall(r'(?:^|[?:(]|\|\|)\s*(\d+|GKS_E_\w+)\s*(?=$|[:)?]|\|\|)', m.group(1).strip()):
                self._lit(v, out)
        for m in re.finditer(r'\breturn\s+([^;]+);', body):
            for v in re.findall(r'(?:^|[?:(])\s*(\d+)\s*(?=$|[:)?])', m.group(1).strip()):
                if int(v) >= 20:
                    self._lit(v, out)
        for m in re.finditer(r'\b([A-Za-z_]\w*)\s*\(', body):
            ident = m.group(1)
            # gks_record_open (GKS3D_RECORD) reports its failures on stderr, never to
            # ERROR HANDLING: its callees' errors are not OPEN GKS's
            if ident in ('gks_ws_checked', 'gks_check_state', 'gks_inq_state', 'gks_inq_begin',
                         'gks_record_open',
                         'if', 'while', 'for', 'switch', 'return', 'sizeof'):
                continue
            mac = self.macros.get(ident)
            if mac and mac[0] is not None:
                key = (ident, call_args(body, m.end() - 1))
                if key not in seen:
                    seen.add(key)
                    self._walk_body(path, self.expand(ident, key[1]), seen, out)
                continue
            fpath, fbody = self.lookup(path, ident)
            if fbody is None:
                continue
            # error numbers passed as arguments (rep_ws(..., 60, ...): parameters named
            # err..., bad..., not..., undef...) replace the parameter in the callee's body
            lits = tuple((q, a) for q, a in zip(self.params.get((fpath, ident), []),
                                                split_args(call_args(body, m.end() - 1)))
                         if re.fullmatch(r'\d+', a) and re.search(r'err|bad|not|undef', q.lower()))
            key = (fpath, ident, lits)
            if key in seen or (fpath, ident, ()) in seen and not lits:
                continue
            seen.add(key)
            if lits:
                sub = dict(lits)
                fbody = re.sub(r'[A-Za-z_]\w*', lambda x: sub.get(x.group(0), x.group(0)), fbody)
            self._walk_body(fpath, fbody, seen, out)
        for ident in set(re.findall(r'\b([A-Z_][A-Z0-9_]*)\b', body)):
            mac = self.macros.get(ident)
            if mac and mac[0] is None and ident not in seen:
                seen.add(ident)
                self._walk_body(path, mac[1], seen, out)

    def _lit(self, v, out):
        n = int(v) if v.isdigit() else self.consts.get(v)
        if n is not None and n in self.known and n > 8:
            out.add(n)


def split_args(args):
    out, depth, cur = [], 0, ''
    for ch in args:
        if ch in '([{':
            depth += 1
        elif ch in ')]}':
            depth -= 1
        if ch == ',' and depth == 0:
            out.append(cur.strip())
            cur = ''
        else:
            cur += ch
    out.append(cur.strip())
    return out



# ------------------------------------------------------------------ the hand-written text
def parse_names():
    out = {}
    for line in read('docs/man/src/names.txt').split('\n'):
        if line.strip() and not line.startswith('#'):
            name, iso = line.split(None, 1)
            out[name] = iso.strip()
    return out


KEYS = ('summary', 'desc', 'defaults', 'example', 'fexample', 'see', 'errors', 'notes')


def parse_records():
    """The records of docs/man/src/*.txt: '@ name name ...' starts one (its C functions,
    the first carries the page); then 'key: text' lines, 'arg NAMES: text' for arguments
    (C and Fortran names, blank separated) and 'fsig NAME: A, B' (the Fortran argument
    names of NAME, when the wrapper's are not the standard's); a key's text goes on over
    the lines indented by blanks (an empty line inside: a new paragraph)."""
    recs = []
    d = os.path.join(ROOT, 'docs/man/src')
    for fn in sorted(os.listdir(d)):
        if not fn.endswith('.txt') or fn in ('names.txt', 'glossary.txt'):
            continue
        cur = None
        key = None
        for no, line in enumerate(read('docs/man/src/' + fn).split('\n'), 1):
            where = '%s:%d' % (fn, no)
            if line.startswith('#'):
                continue
            if line.startswith('@'):
                cur = {'names': line[1:].split(), 'args': [], 'fsig': {}, 'where': where,
                       'file': fn}
                recs.append(cur)
                key = None
                continue
            if cur is None:
                if line.strip():
                    raise SystemExit('%s: text outside a record' % where)
                continue
            if line[:1] not in (' ', '') :
                m = re.match(r'(\w+)((?: +[\w.]+)*):(.*)$', line)
                if not m:
                    raise SystemExit('%s: not "key: text"' % where)
                k, names, rest = m.group(1), m.group(2).split(), m.group(3).strip()
                if k == 'arg':
                    cur['args'].append([names, rest])
                    key = ('arg', len(cur['args']) - 1)
                elif k == 'moreerrors':
                    for n in names:
                        cur.setdefault('more_of', {})[n] = rest
                    key = None
                elif k == 'errors' and names:
                    for n in names:
                        cur.setdefault('errors_of', {})[n] = rest
                    key = None
                elif k == 'fsig':
                    cur['fsig'][names[0]] = [a.strip() for a in rest.split(',') if a.strip()]
                    key = None
                elif k in KEYS:
                    cur[k] = rest
                    key = k
                else:
                    raise SystemExit('%s: unknown key %s' % (where, k))
                continue
            if key is None:
                if line.strip():
                    raise SystemExit('%s: continuation without a key' % where)
                continue
            if key[0] == 'arg':
                cur['args'][key[1]][1] += '\n' + line
            else:
                cur[key] += '\n' + line
    return recs


def parse_glossary():
    """{argument name: text} of docs/man/src/glossary.txt."""
    out = {}
    for line in read('docs/man/src/glossary.txt').split('\n'):
        if line.strip() and not line.startswith('#'):
            names, text = line.split(':', 1)
            for n in names.split():
                out[n] = text.strip()
    return out


def paragraphs(text):
    """Text -> [('p', text) | ('pre', lines)]: lines indented by 4 or more blanks (beyond the
    continuation's one) are preformatted."""
    out = []
    cur = []
    pre = []
    for line in text.split('\n'):
        if line.startswith('     ') and (pre or not cur):
            pre.append(line[5:])
            continue
        if pre:
            out.append(('pre', pre))
            pre = []
        if not line.strip():
            if cur:
                out.append(('p', ' '.join(cur)))
                cur = []
        else:
            cur.append(line.strip())
    if pre:
        out.append(('pre', pre))
    if cur:
        out.append(('p', ' '.join(cur)))
    return out


def code_block(text):
    lines = text.split('\n')
    if lines and not lines[0].strip():
        lines = lines[1:]
    while lines and not lines[-1].strip():
        lines.pop()
    # the record's indentation is five blanks: removed, and no more, so that FORTRAN
    # 77 fixed form keeps its statements in column 7
    ind = min([len(l) - len(l.lstrip()) for l in lines if l.strip()] + [5])
    return [l[ind:] for l in lines]


# ------------------------------------------------------------------ model
class Model:
    def __init__(self):
        self.table = parse_table()
        self.cnames = table_c_names()
        self.c = parse_c_header()
        self.cby = {x['name']: x for x in self.c}
        self.f = parse_fortran(set(self.cby))
        self.f.pop('UPPER', None)
        self.errmsg = errors_def()
        self.names = parse_names()
        self.glossary = parse_glossary()
        self.src = SourceErrors(set(self.errmsg))
        self.sym_of = {c: s for s, c in self.cnames.items()}
        # C function -> its Fortran names
        self.fort = collections.defaultdict(list)
        for k in sorted(self.f):
            if self.f[k]['c']:
                self.fort[self.f[k]['c']].append(k)
        self.fonly = sorted(k for k in self.f if not self.f[k]['c'])
        # records: every C function in exactly one; the others get one each
        self.recs = parse_records()
        self.rec_of = {}
        for r in self.recs:
            for n in r['names']:
                if n in self.rec_of:
                    raise SystemExit('%s: %s is already in %s' % (r['where'], n, self.rec_of[n]['where']))
                if n not in self.cby and n not in self.fonly:
                    raise SystemExit('%s: %s is no C entry point (nor a Fortran-only one)' % (r['where'], n))
                self.rec_of[n] = r
        for x in self.c:
            if x['name'] not in self.rec_of:
                r = {'names': [x['name']], 'args': [], 'fsig': {}, 'auto': True, 'where': 'generated'}
                self.recs.append(r)
                self.rec_of[x['name']] = r
        for k in self.fonly:
            if k not in self.rec_of:
                r = {'names': [k], 'args': [], 'fsig': {}, 'auto': True, 'where': 'generated'}
                self.recs.append(r)
                self.rec_of[k] = r
        order = {x['name']: i for i, x in enumerate(self.c)}
        self.recs.sort(key=lambda r: (order.get(r['names'][0], 10 ** 6), r['names'][0]))
        for r in self.recs:
            self.check_args(r)

    def iso(self, name):
        sym = self.sym_of.get(name)
        if sym:
            return self.table[sym]['iso']
        if name in self.names:
            return self.names[name]
        raise SystemExit('no ISO name for %s: add it to docs/man/src/names.txt' % name)

    def fid(self, name):
        sym = self.sym_of.get(name)
        return self.table[sym]['id'] if sym else None

    def fargs(self, fname):
        a = self.f[fname]['args']
        r = self.rec_of.get(self.f[fname]['c'] or fname)
        ren = r['fsig'].get(fname) if r else None
        if ren:
            if len(ren) != len(a):
                raise SystemExit('%s: fsig %s has %d names, the wrapper %d arguments' % (r['where'], fname, len(ren), len(a)))
            a = [(re.sub(r'\(.*', '', n), t, io) for n, (_, t, io) in zip(ren, a)]
        return a

    def fdims(self, fname):
        """{argument: '(4,4)'}: the array dimensions the wrapper's comment gives
        ("GSVWR(WKID, VWI, VWM(4,4), ...)"), where its names are the wrapper's."""
        c = self.f[fname].get('comment', '')
        m = re.match(re.escape(fname) + r'\(', c)
        if not m:
            return {}
        parts = split_args(call_args(c, m.end() - 1))
        names = [a[0] for a in self.f[fname]['args']]
        out = {}
        if len(parts) != len(names):
            return {}
        for part, n in zip(parts, names):
            pm = re.fullmatch(r'(\w+)\s*(\([^()]*\))?', part.strip())
            if not pm or pm.group(1).upper() != n:
                return {}
            if pm.group(2):
                out[n] = pm.group(2).replace(' ', '')
        return out

    def c_params(self, name):
        out = []
        args = self.cby[name]['args']
        if args == 'void':
            return out
        for p in split_args(args):
            m = re.search(r'(\w+)\s*(\[[^\]]*\])*$', p)
            out.append(m.group(1) if m else p)
        return out

    def check_args(self, r):
        if r.get('auto'):
            return
        known = set()
        for n in r['names']:
            if n in self.cby:
                known |= set(self.c_params(n))
                for fn in self.fort.get(n, []):
                    known |= {a[0] for a in self.fargs(fn)}
            else:
                known |= {a[0] for a in self.fargs(n)}
        for names, _ in r['args']:
            for n in names:
                if n not in known:
                    raise SystemExit('%s: argument %s is in no signature of %s' % (r['where'], n, ' '.join(r['names'])))

    def state_error(self, name):
        sym = self.sym_of.get(name)
        if sym:
            return self.table[sym]['state_err']
        path = self.src.file_of.get(name)
        seen = set()
        todo = [(path, self.src.funcs.get(name, ''))]
        while todo:
            path, b = todo.pop(0)
            m = re.search(r'gks_inq_(?:state|begin)\s*\(([^;]*?)\)', b)
            if m and re.findall(r'GKS_S_\w+', m.group(1)):
                return mask_error('|'.join(re.findall(r'GKS_S_\w+', m.group(1))))
            for ident in re.findall(r'\b([A-Za-z_]\w*)\s*\(', b):
                if ident in seen:
                    continue
                seen.add(ident)
                fpath, fbody = self.src.lookup(path, ident)
                if fbody is not None:
                    todo.append((fpath, fbody))
                elif ident in self.src.macros:
                    todo.append((path, self.src.macros[ident][1]))
        return 0

    def header_errors(self, name):
        x = self.cby.get(name)
        if not x:
            return set()
        out = set()
        # only the comment directly above and the one after the declaration: a group
        # comment's list mixes its functions' errors
        for c in (x['comment'] if x.get('direct') else '', x['trail']):
            c = re.sub(r'PHIGS \d+', '', c)
            m = re.search(r'Errors?(?: \(in \*err_ind\))?:\s*(.*)', c)
            if m:
                # the list: numbers up to the end of its sentence, remarks in brackets
                # (ranges such as "1..64") left out
                lst = m.group(1)
                while re.search(r'\([^()]*\)', lst):
                    lst = re.sub(r'\([^()]*\)', '', lst)
                lst = re.split(r'\.(?:\s|$)|;', lst)[0]
                out |= {int(v) for v in re.findall(r'(?<![\w.])(\d+)(?![\w]|\.\d)', lst)}
            elif c is x['trail']:
                m = re.match(r'([\d, ]+)(?::|$)', c)
                if m:
                    out |= {int(v) for v in re.findall(r'\d+', m.group(1))}
        return {e for e in out if e in self.errmsg}

    def errors(self, name):
        """(state error, [argument errors]) of a C entry point."""
        r = self.rec_of.get(name)
        st = self.state_error(name)
        hand = (r.get('errors_of', {}).get(name) or r.get('errors')) if r else None
        if hand:
            errs = {int(v) for v in re.findall(r'\d+', hand)}
        else:
            errs = self.src.errors(name) | self.header_errors(name)
        if r and r.get('more_of', {}).get(name):
            errs |= {int(v) for v in re.findall(r'\d+', r['more_of'][name])}
        errs = tuple(sorted(e for e in errs if e > 8))
        return st, errs

    def reports_in_indicator(self, name):
        """Inquiries and the view evaluation utilities answer errors in err_ind."""
        return 'err_ind' in self.c_params(name)

    def is_inquiry(self, name):
        return name.startswith('ginq_') or self.iso(name).startswith('INQUIRE')


# ------------------------------------------------------------------ rendering
COORDS = ('WC', 'NDC', 'NPC', 'DC', 'VRC', 'WC3', 'NDC3', 'NPC3', 'DC3', 'VRC3')


def man_escape(s):
    s = s.replace('\\', '\\e').replace('-', '\\-')
    return s


def man_inline(s):
    """`code` -> bold, the rest escaped; a line may not start with . or '."""
    parts = re.split(r'`([^`]*)`', s)
    out = ''
    for i, p in enumerate(parts):
        out += ('\\fB' + man_escape(p) + '\\fR') if i % 2 else man_escape(p)
    return out


def man_text(s):
    out = []
    for line in s.split('\n'):
        line = man_inline(line)
        if line.startswith(('.', "'")):
            line = '\\&' + line
        out.append(line)
    return '\n'.join(out)


def man_pre(lines):
    out = ['.PP', '.RS 4', '.nf']
    for l in lines:
        l = man_escape(l)
        if l.startswith(('.', "'")):
            l = '\\&' + l
        out.append(l if l else '')
    out += ['.fi', '.RE']
    return out


def md_inline(s):
    return s


class Page:
    """The content of one page (a record), built once, written as man and Markdown."""

    def __init__(self, m, r):
        self.m = m
        self.r = r
        self.cfuncs = [n for n in r['names'] if n in m.cby]
        self.ffuncs = []
        for n in r['names']:
            if n in m.cby:
                self.ffuncs += m.fort.get(n, [])
            else:
                self.ffuncs.append(n)
        self.main = r['names'][0]

    def iso_names(self):
        out = []
        for n in self.r['names']:
            i = self.m.iso(n) if n in self.m.cby else self.m.names.get(n, n)
            if i not in out:
                out.append(i)
        return out

    def summary(self):
        if self.r.get('summary'):
            return ' '.join(self.r['summary'].split())
        if self.main in self.m.cby:
            c = self.m.cby[self.main]
            if c.get('direct') and c['comment']:
                first = re.split(r'(?<=[.:])\s', c['comment'], 1)[0].rstrip('.:')
                if len(first) < 100 and first.upper() != first:
                    return first
        return ''

    def c_synopsis(self):
        out = []
        for n in self.cfuncs:
            c = self.m.cby[n]
            out.append('%s %s(%s);' % (c['ret'], n, c['args']))
        return out

    def f_synopsis(self):
        out = []
        for f in self.ffuncs:
            a = self.m.fargs(f)
            out.append(('CALL %s(%s)' % (f, ', '.join(x[0] for x in a))) if a else 'CALL %s' % f)
        return out

    def f_decls(self, f):
        a = self.m.fargs(f)
        ren = self.r['fsig'].get(f)
        if ren:  # fsig names with dimensions: PX(N)
            dims = {re.sub(r'\(.*', '', x): x[len(re.sub(r'\(.*', '', x)):] for x in ren}
        else:
            dims = self.m.fdims(f)
        by = collections.OrderedDict()
        for n, t, io in a:
            by.setdefault(t, []).append(n + dims.get(n, ''))
        return ['%s %s' % (t, ', '.join(ns)) for t, ns in by.items()]

    def arg_items(self):
        """[(names, text)]: the record's arguments, then every argument of the
        signatures no record line describes (its C type or Fortran type and direction)."""
        items = [(names, text) for names, text in self.r['args']]
        done = {n for names, _ in items for n in names}
        rest = []
        for n in self.cfuncs:
            params = self.m.c_params(n)
            decl = split_args(self.m.cby[n]['args']) if self.m.cby[n]['args'] != 'void' else []
            for p, d in zip(params, decl):
                if p not in done:
                    done.add(p)
                    out = 'output' if ('*' in d and not d.startswith('const')) or (
                        '[' in d and not d.startswith('const')) else 'input'
                    gl = self.m.glossary.get(p)
                    rest.append(([p], ('%s (C `%s`, %s.)' % (gl, ' '.join(d.split()), out)) if gl
                                 else '(C) `%s`, %s.' % (' '.join(d.split()), out)))
        for f in self.ffuncs:
            for n, t, io in self.m.fargs(f):
                if n not in done:
                    done.add(n)
                    gl = self.m.glossary.get(n)
                    io_s = 'input' if io == 'in' else 'output'
                    rest.append(([n], ('%s (FORTRAN %s, %s.)' % (gl, t, io_s)) if gl
                                 else '(FORTRAN) %s, %s.' % (t, io_s)))
        return items, rest

    def errors(self):
        """[(state error or None, [errors])] per C function, merged when equal."""
        res = collections.OrderedDict()
        for n in self.cfuncs:
            res.setdefault(self.m.errors(n), []).append(n)
        return res

    def hand_errors(self):
        return bool(self.r.get('errors') or self.r.get('errors_of'))

    def handwritten(self):
        return not self.r.get('auto')


def see_also(m, p):
    names = []
    if p.r.get('see'):
        names = p.r['see'].split()
    return names


def render_man(m, p):
    out = []
    title = p.main.upper() if p.main in m.cby else p.main.upper()
    out.append('.\\" Generated by scripts/gen_man.py from docs/man/src (do not edit).')
    # no version or date in the footer: a release would change every page
    out.append('.TH %s 3 "" "gks3d" "gks3d reference"' % man_escape(title))
    out.append('.SH NAME')
    names = p.cfuncs + p.ffuncs
    summ = p.summary()
    iso = ', '.join(p.iso_names())
    out.append('%s \\- %s' % (', '.join(man_escape(n) for n in names),
                              man_escape(iso + (': ' + summ if summ else ''))))
    out.append('.SH SYNOPSIS')
    if p.cfuncs:
        out.append('.SS C')
        out.append('.nf')
        out.append('.B #include <gks.h>')
        out.append('.PP')
        for s in p.c_synopsis():
            out.append(man_escape(s))
        out.append('.fi')
        out.append('.PP')
        out.append('Link with \\fB\\-lgks3d\\fR (pkg\\-config \\fBgks3d\\fR).')
    if p.ffuncs:
        out.append('.SS FORTRAN 77')
        out.append('.nf')
        for f, s in zip(p.ffuncs, p.f_synopsis()):
            out.append(man_escape(s))
            for d in p.f_decls(f):
                out.append('    ' + man_escape(d))
        out.append('.fi')
        out.append('.PP')
        out.append('Link with \\fB\\-lgks3d_fortran \\-lgks3d\\fR (pkg\\-config \\fBgks3d\\-fortran\\fR).')
    if not p.ffuncs:
        out.append('.PP')
        out.append('The FORTRAN 77 binding has no counterpart of this function.')
    if not p.cfuncs:
        out.append('.PP')
        out.append('The C binding has no counterpart of this function.')
    ids = [(n, m.fid(n)) for n in p.cfuncs if m.fid(n) is not None]
    if ids:
        out.append('.PP')
        out.append('Function identification (passed to ERROR HANDLING): %s.' %
                   ', '.join('%d (%s)' % (i, man_escape(n)) for n, i in ids))
    out.append('.SH DESCRIPTION')
    if p.r.get('desc'):
        out += render_blocks_man(p.r['desc'])
    else:
        c = m.cby.get(p.main)
        if c and c['comment'] and (c.get('direct') or c['trail']):
            out.append('From the header (include/gks.h):')
            out.append('.PP')
            out.append(man_text(c['comment'] + ((' ' + c['trail']) if c['trail'] else '')))
        elif c and c['trail']:
            out.append(man_text('Errors beyond the state error (include/gks.h): ' + c['trail']))
        else:
            out.append(man_text('%s, as ISO 7942 / ISO 8805 define it; see the arguments below and gks3d(7).' % ', '.join(p.iso_names())))
        if all(m.is_inquiry(n) for n in p.cfuncs) and p.cfuncs:
            out.append('.PP')
            out.append(man_text(INQ_NOTE))
    items, rest = p.arg_items()
    if items or rest:
        out.append('.SH ARGUMENTS')
        for names, text in items + rest:
            out.append('.TP')
            out.append('.B ' + man_escape(', '.join(names)))
            blocks = render_blocks_man(text)
            if blocks and blocks[0] == '.PP':
                blocks = blocks[1:]
            out += blocks
    if p.r.get('defaults'):
        out.append('.SH DEFAULTS')
        out += render_blocks_man(p.r['defaults'])
    if p.r.get('notes'):
        out.append('.SH NOTES')
        out += render_blocks_man(p.r['notes'])
    errs = p.errors()
    if errs:
        out.append('.SH ERRORS')
        inq = p.cfuncs and all(m.reports_in_indicator(n) for n in p.cfuncs)
        if inq:
            out.append(man_text('Returned in the error indicator (`err_ind`, Fortran `ERRIND`); ERROR HANDLING is not called.'))
        else:
            out.append(man_text('Reported through ERROR HANDLING (gerr_hand(3), Fortran GERHND) with the function identification above; unless the description says otherwise the function then has no effect.'))
        for (st, el), fns in errs.items():
            if len(errs) > 1:
                out.append('.PP')
                out.append('.B ' + man_escape(', '.join(fns)) + ':')
            if st:
                out.append('.TP')
                out.append('.B %d' % st)
                out.append(man_text(m.errmsg[st]))
            for e in el:
                out.append('.TP')
                out.append('.B %d' % e)
                out.append(man_text(m.errmsg[e]))
            if not st and not el:
                out.append('.PP')
                out.append('None: callable in every state.')
        src = 'hand\\-checked' if p.hand_errors() else 'read from the entry point\'s source and include/gks.h (an error of a helper shared with other functions may be listed for all of them)'
        out.append('.PP')
        out.append('Error list %s; docs/ERRORS.md explains each number.' % src)
    if p.r.get('example') or p.r.get('fexample'):
        out.append('.SH EXAMPLE')
        if p.r.get('example'):
            out += man_pre(code_block(p.r['example']))
        if p.r.get('fexample'):
            out += man_pre(code_block(p.r['fexample']))
    see = [s for s in see_also(m, p) if s != p.main]
    out.append('.SH SEE ALSO')
    refs = ['.BR gks3d (7)']
    for s in see:
        refs.append('.BR %s (3)' % man_escape(s))
    for i in range(len(refs) - 1):
        refs[i] += ' ,'
    out += refs
    return '\n'.join(out) + '\n'


INQ_NOTE = ('An inquiry: it never calls ERROR HANDLING; the error indicator receives 0 or the '
            'error number, and the other outputs are written only when it is 0. List inquiries '
            'take the capacity of the application\'s list and a 0-based start position and return '
            'the implementation\'s list length (Fortran: the N-th element, 1-based, N = 0 for the '
            'length only).')


def render_blocks_man(text):
    out = []
    for kind, v in paragraphs(text):
        if kind == 'p':
            out.append('.PP')
            out.append(man_text(v))
        else:
            out += man_pre(v)
    return out


def render_md_blocks(text):
    out = []
    for kind, v in paragraphs(text):
        if kind == 'p':
            out.append(v)
        else:
            out.append('```\n' + '\n'.join(v) + '\n```')
        out.append('')
    return out


def render_md(m, p):
    out = []
    names = p.cfuncs + p.ffuncs
    out.append('# %s' % ', '.join(p.iso_names()))
    out.append('')
    out.append('<!-- Generated by scripts/gen_man.py from docs/man/src (do not edit). -->')
    out.append('')
    summ = p.summary()
    out.append('`%s`%s' % ('`, `'.join(names), (' — ' + summ) if summ else ''))
    out.append('')
    out.append('## Synopsis')
    out.append('')
    if p.cfuncs:
        out.append('```c\n#include <gks.h>\n\n' + '\n'.join(p.c_synopsis()) + '\n```')
        out.append('')
    if p.ffuncs:
        fl = []
        for f, s in zip(p.ffuncs, p.f_synopsis()):
            fl.append(s)
            fl += ['    ' + d for d in p.f_decls(f)]
        out.append('```fortran\n' + '\n'.join(fl) + '\n```')
        out.append('')
    else:
        out.append('The FORTRAN 77 binding has no counterpart of this function.')
        out.append('')
    if not p.cfuncs:
        out.append('The C binding has no counterpart of this function.')
        out.append('')
    ids = [(n, m.fid(n)) for n in p.cfuncs if m.fid(n) is not None]
    if ids:
        out.append('Function identification (passed to ERROR HANDLING): %s.' %
                   ', '.join('%d (`%s`)' % (i, n) for n, i in ids))
        out.append('')
    out.append('## Description')
    out.append('')
    if p.r.get('desc'):
        out += render_md_blocks(p.r['desc'])
    else:
        c = m.cby.get(p.main)
        if c and c['comment'] and (c.get('direct') or c['trail']):
            out.append('From the header (`include/gks.h`):')
            out.append('')
            out.append(c['comment'] + ((' ' + c['trail']) if c['trail'] else ''))
        elif c and c['trail']:
            out.append('Errors beyond the state error (`include/gks.h`): ' + c['trail'])
        else:
            out.append('%s, as ISO 7942 / ISO 8805 define it; see the arguments below and [gks3d(7)](gks3d.7.md).' % ', '.join(p.iso_names()))
        out.append('')
        if p.cfuncs and all(m.is_inquiry(n) for n in p.cfuncs):
            out.append(INQ_NOTE)
            out.append('')
    items, rest = p.arg_items()
    if items or rest:
        out.append('## Arguments')
        out.append('')
        for names, text in items + rest:
            body = ' '.join(x if k == 'p' else '\n```\n' + '\n'.join(x) + '\n```\n'
                            for k, x in paragraphs(text))
            out.append('- **%s**: %s' % (', '.join(names), body))
        out.append('')
    for key, head in (('defaults', 'Defaults'), ('notes', 'Notes')):
        if p.r.get(key):
            out.append('## ' + head)
            out.append('')
            out += render_md_blocks(p.r[key])
    errs = p.errors()
    if errs:
        out.append('## Errors')
        out.append('')
        inq = p.cfuncs and all(m.reports_in_indicator(n) for n in p.cfuncs)
        out.append('Returned in the error indicator (`err_ind`, Fortran `ERRIND`); ERROR HANDLING is not called.'
                   if inq else
                   'Reported through ERROR HANDLING (`gerr_hand`, Fortran `GERHND`) with the function identification above; unless the description says otherwise the function then has no effect.')
        out.append('')
        for (st, el), fns in errs.items():
            if len(errs) > 1:
                out.append('`%s`:' % '`, `'.join(fns))
                out.append('')
            if st:
                out.append('- **%d** %s' % (st, m.errmsg[st]))
            for e in el:
                out.append('- **%d** %s' % (e, m.errmsg[e]))
            if not st and not el:
                out.append('None: callable in every state.')
            out.append('')
        out.append('Error list %s; [ERRORS.md](../ERRORS.md) explains each number.' %
                   ('hand-checked' if p.hand_errors() else "read from the entry point's source and `include/gks.h` (an error of a helper shared with other functions may be listed for all of them)"))
        out.append('')
    if p.r.get('example') or p.r.get('fexample'):
        out.append('## Example')
        out.append('')
        if p.r.get('example'):
            out.append('```c\n' + '\n'.join(code_block(p.r['example'])) + '\n```')
            out.append('')
        if p.r.get('fexample'):
            out.append('```fortran\n' + '\n'.join(code_block(p.r['fexample'])) + '\n```')
            out.append('')
    see = [s for s in see_also(m, p) if s != p.main]
    out.append('## See also')
    out.append('')
    links = ['[gks3d(7)](gks3d.7.md)']
    for s in see:
        links.append('[%s](%s.md)' % (s, page_name(m.rec_of[s]['names'][0] if s in m.rec_of else s)))
    out.append(', '.join(links))
    out.append('')
    return '\n'.join(out)


def page_name(n):
    """The page file name of a function: C names as they are, Fortran names in lower case."""
    return n.lower() if n.isupper() else n


def outputs(m):
    """{relative path: content} of everything generated."""
    files = {}
    index = []
    for r in m.recs:
        p = Page(m, r)
        main = page_name(p.main)
        files['docs/man/man3/%s.3' % main] = render_man(m, p)
        files['docs/reference/%s.md' % main] = render_md(m, p)
        for n in r['names'][1:] + [f for f in p.ffuncs if page_name(f) != main]:
            files['docs/man/man3/%s.3' % page_name(n)] = '.so man3/%s.3\n' % main
        index.append(p)
    # the overview
    ov = read('docs/man/gks3d.7.txt')
    files['docs/man/man7/gks3d.7'] = render_overview_man(ov)
    files['docs/reference/gks3d.7.md'] = render_overview_md(ov)
    files['docs/reference/README.md'] = render_index(m, index)
    return files


def render_overview_man(text):
    out = ['.\\" Generated by scripts/gen_man.py from docs/man/gks3d.7.txt (do not edit).',
           '.TH GKS3D 7 "" "gks3d" "gks3d reference"']
    for sec, body in overview_sections(text):
        out.append('.SH ' + man_escape(sec.upper()))
        blocks = render_blocks_man(body)
        if blocks and blocks[0] == '.PP':
            blocks = blocks[1:]
        out += blocks
    return '\n'.join(out) + '\n'


def render_overview_md(text):
    out = ['# gks3d(7): overview', '',
           '<!-- Generated by scripts/gen_man.py from docs/man/gks3d.7.txt (do not edit). -->', '']
    for sec, body in overview_sections(text):
        out.append('## ' + sec)
        out.append('')
        out += render_md_blocks(body)
    return '\n'.join(out)


def overview_sections(text):
    """'= Heading' lines start the sections of docs/man/gks3d.7.txt."""
    secs = []
    for line in text.split('\n'):
        if line.startswith('#'):
            continue
        if line.startswith('= '):
            secs.append([line[2:].strip(), ''])
        elif secs:
            secs[-1][1] += line + '\n'
    return [(a, b) for a, b in secs]


def render_index(m, pages):
    out = ['# gks3d reference', '',
           '<!-- Generated by scripts/gen_man.py (do not edit). -->', '',
           'One page per function of the C binding (`include/gks.h`) and of the FORTRAN 77',
           'binding (`bindings/fortran`), the same text as the installed man pages',
           '(`man gopen_ws`, `man gopwk`, `man 7 gks3d`). Start with the overview,',
           '[gks3d(7)](gks3d.7.md).', '',
           '| ISO name | C | FORTRAN 77 |', '| --- | --- | --- |']
    rows = []
    for p in pages:
        for n in p.r['names']:
            if n in m.cby:
                rows.append((m.iso(n), n, ', '.join(m.fort.get(n, [])) or '—', p.main))
            else:
                rows.append((m.names.get(n, n), '—', n, p.main))
    for iso, c, f, page in sorted(rows):
        out.append('| %s | %s | %s |' % ('[%s](%s.md)' % (iso, page_name(page)), '`%s`' % c if c != '—' else c, f))
    out.append('')
    return '\n'.join(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--out', default=ROOT)
    ap.add_argument('--check', action='store_true')
    ap.add_argument('--stats', action='store_true')
    a = ap.parse_args()
    m = Model()
    files = outputs(m)
    gen_dirs = ['docs/man/man3', 'docs/man/man7', 'docs/reference']
    if a.stats:
        pages3 = [k for k in files if k.startswith('docs/man/man3/')]
        full = [k for k in pages3 if not files[k].startswith('.so ')]
        hand = sum(1 for r in m.recs if not r.get('auto'))
        hand_c = sum(len([n for n in r['names'] if n in m.cby]) for r in m.recs if not r.get('auto'))
        withargs = sum(1 for r in m.recs if r['args'])
        print('C entry points (include/gks.h): %d' % len(m.c))
        print('FORTRAN 77 entry points (bindings/fortran): %d' % len(m.f))
        print('FORTRAN 77 entry points without a C function: %d (%s)' % (len(m.fonly), ' '.join(m.fonly)))
        print('man3 files: %d (%d pages, %d .so links)' % (len(pages3), len(full), len(pages3) - len(full)))
        print('pages with hand-written text: %d of %d (covering %d C functions; %d with argument text)' %
              (hand, len(m.recs), hand_c, withargs))
        own = gl = bare = 0
        for r in m.recs:
            items, rest = Page(m, r).arg_items()
            own += sum(len(n) for n, _ in items)
            bare += sum(1 for _, t in rest if t.startswith(('(C)', '(FORTRAN)')))
            gl += sum(1 for _, t in rest if not t.startswith(('(C)', '(FORTRAN)')))
        print('argument entries: %d by the page\'s text, %d by the glossary, %d type and direction only' %
              (own, gl, bare))
        return 0
    if a.check:
        bad = 0
        for d in gen_dirs:
            path = os.path.join(a.out, d)
            have = set(os.listdir(path)) if os.path.isdir(path) else set()
            want = {k.split('/')[-1] for k in files if k.startswith(d + '/')}
            for x in sorted(have - want):
                print('stale: %s/%s' % (d, x))
                bad = 1
        for k, v in sorted(files.items()):
            path = os.path.join(a.out, k)
            try:
                with open(path, encoding='utf-8') as f:
                    if f.read() == v:
                        continue
            except OSError:
                pass
            print('differs: %s' % k)
            bad = 1
        if bad:
            print('run scripts/gen_man.py to regenerate')
        return bad
    for d in gen_dirs:
        path = os.path.join(a.out, d)
        if os.path.isdir(path):
            for x in os.listdir(path):
                os.unlink(os.path.join(path, x))
        os.makedirs(path, exist_ok=True)
    for k, v in files.items():
        with open(os.path.join(a.out, k), 'w', encoding='utf-8') as f:
            f.write(v)
    return 0


if __name__ == '__main__':
    sys.exit(main())
