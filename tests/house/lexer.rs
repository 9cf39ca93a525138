//! A small Rust lexer for the house-rule checks: identifiers, punctuation and literals with
//! their line numbers; comments dropped; string, raw-string, byte and char literals kept whole
//! (so the text inside them is never code); lifetimes told apart from char literals. Plus the
//! token-level helpers the checks need: matching braces, `#[cfg(test)]` items, inline module
//! scopes, `use`-tree paths, and Tarjan's strongly connected components.

use std::collections::{BTreeMap, BTreeSet};

/// A token's kind.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Tok {
    /// An identifier or keyword (`r#raw` without its prefix).
    Ident(String),
    /// One punctuation character.
    Punct(char),
    /// A string, char, byte or number literal.
    Lit,
}

/// A token and the 1-based line it starts on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Token {
    pub tok: Tok,
    pub line: usize,
}

/// The tokens of `src`.
pub fn lex(src: &str) -> Vec<Token> {
    let c: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let (mut i, mut line) = (0, 1);
    let at = |k: usize| c.get(k).copied().unwrap_or('\0');
    while i < c.len() {
        let ch = c[i];
        let start_line = line;
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch == '/' && at(i + 1) == '/' {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if ch == '/' && at(i + 1) == '*' {
            // block comments nest in Rust
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && at(i + 1) == '*' {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && at(i + 1) == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    line += usize::from(c[i] == '\n');
                    i += 1;
                }
            }
        } else if ch == '"' {
            i = skip_string(&c, i, &mut line);
            out.push(Token { tok: Tok::Lit, line: start_line });
        } else if ch == '\'' {
            if at(i + 1) == '\\' {
                // an escaped char literal: to the closing quote
                i += 2;
                while i < c.len() && c[i] != '\'' {
                    i += 1;
                }
                i += 1;
                out.push(Token { tok: Tok::Lit, line: start_line });
            } else if at(i + 2) == '\'' {
                i += 3;
                out.push(Token { tok: Tok::Lit, line: start_line });
            } else {
                // a lifetime or label: the quote, then the identifier as usual
                out.push(Token { tok: Tok::Punct('\''), line: start_line });
                i += 1;
            }
        } else if ch.is_alphabetic() || ch == '_' {
            let s = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            let word: String = c[s..i].iter().collect();
            let prefix = matches!(word.as_str(), "r" | "b" | "br" | "c" | "cr");
            if prefix
                && (at(i) == '"' || (word.contains('r') && at(i) == '#' && matches!(at(i + 1), '"' | '#')))
            {
                i = if word.contains('r') {
                    skip_raw_string(&c, i, &mut line)
                } else {
                    skip_string(&c, i, &mut line)
                };
                out.push(Token { tok: Tok::Lit, line: start_line });
            } else if word == "b" && at(i) == '\'' {
                i += if at(i + 1) == '\\' { 4 } else { 3 };
                while i < c.len() && c[i - 1] != '\'' {
                    i += 1;
                }
                out.push(Token { tok: Tok::Lit, line: start_line });
            } else if word == "r" && at(i) == '#' && (at(i + 1).is_alphabetic() || at(i + 1) == '_') {
                // a raw identifier r#name
                let s = i + 1;
                i = s;
                while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                    i += 1;
                }
                out.push(Token { tok: Tok::Ident(c[s..i].iter().collect()), line: start_line });
            } else {
                out.push(Token { tok: Tok::Ident(word), line: start_line });
            }
        } else if ch.is_ascii_digit() {
            // digits, suffixes and a decimal point followed by a digit (not the `..` of a range)
            while i < c.len()
                && (c[i].is_alphanumeric() || c[i] == '_' || (c[i] == '.' && at(i + 1).is_ascii_digit()))
            {
                i += 1;
            }
            out.push(Token { tok: Tok::Lit, line: start_line });
        } else {
            out.push(Token { tok: Tok::Punct(ch), line: start_line });
            i += 1;
        }
    }
    out
}

/// Past the closing quote of the string opening at `c[i]` (`"`), counting newlines.
fn skip_string(c: &[char], mut i: usize, line: &mut usize) -> usize {
    i += 1;
    while i < c.len() && c[i] != '"' {
        if c[i] == '\\' {
            *line += usize::from(c.get(i + 1) == Some(&'\n'));
            i += 1;
        } else if c[i] == '\n' {
            *line += 1;
        }
        i += 1;
    }
    i + 1
}

/// Past the raw string whose hashes or opening quote start at `c[i]` (`r#"…"#`).
fn skip_raw_string(c: &[char], mut i: usize, line: &mut usize) -> usize {
    let mut hashes = 0;
    while c.get(i) == Some(&'#') {
        hashes += 1;
        i += 1;
    }
    i += 1; // the opening quote
    while i < c.len() {
        if c[i] == '"' && (1..=hashes).all(|k| c.get(i + k) == Some(&'#')) {
            return i + 1 + hashes;
        }
        *line += usize::from(c[i] == '\n');
        i += 1;
    }
    i
}

/// The index of the bracket closing the one at `open` (`{`, `(` or `[`).
pub fn matching(toks: &[Token], open: usize) -> Option<usize> {
    let (o, cl) = match toks[open].tok {
        Tok::Punct('{') => ('{', '}'),
        Tok::Punct('(') => ('(', ')'),
        Tok::Punct('[') => ('[', ']'),
        _ => return None,
    };
    let mut depth = 0usize;
    for (k, t) in toks.iter().enumerate().skip(open) {
        if t.tok == Tok::Punct(o) {
            depth += 1;
        } else if t.tok == Tok::Punct(cl) {
            depth -= 1;
            if depth == 0 {
                return Some(k);
            }
        }
    }
    None
}

/// Whether `toks[i]`, `toks[i + 1]` are the path separator `::`.
pub fn is_path_sep(toks: &[Token], i: usize) -> bool {
    toks.get(i).is_some_and(|t| t.tok == Tok::Punct(':'))
        && toks.get(i + 1).is_some_and(|t| t.tok == Tok::Punct(':'))
}

/// The tokens without the items marked `#[cfg(test)]` (a test module, a test-only `use` or
/// function): from the attribute to the end of the item's braces, or to its `;`.
pub fn without_test_items(toks: &[Token]) -> Vec<Token> {
    let ident = |t: &Token, s: &str| t.tok == Tok::Ident(s.into());
    let mut out = Vec::with_capacity(toks.len());
    let mut i = 0;
    while i < toks.len() {
        let is_cfg_test = toks[i].tok == Tok::Punct('#')
            && toks.get(i + 1).is_some_and(|t| t.tok == Tok::Punct('['))
            && toks.get(i + 2).is_some_and(|t| ident(t, "cfg"))
            && toks.get(i + 3).is_some_and(|t| t.tok == Tok::Punct('('))
            && toks.get(i + 4).is_some_and(|t| ident(t, "test"))
            && toks.get(i + 5).is_some_and(|t| t.tok == Tok::Punct(')'));
        if !is_cfg_test {
            out.push(toks[i].clone());
            i += 1;
            continue;
        }
        // the item ends at the first `;` or at the brace closing its first `{`
        let mut k = i + 6;
        while k < toks.len() && toks[k].tok != Tok::Punct(';') && toks[k].tok != Tok::Punct('{') {
            k += 1;
        }
        i = if k < toks.len() && toks[k].tok == Tok::Punct('{') {
            matching(toks, k).map_or(toks.len(), |e| e + 1)
        } else {
            k + 1
        };
    }
    out
}

/// For each token, the module it is in: `file_module` plus the inline `mod name { … }` blocks
/// around it.
pub fn inline_scopes(toks: &[Token], file_module: &[String]) -> Vec<Vec<String>> {
    let mut out = Vec::with_capacity(toks.len());
    let mut scope = file_module.to_vec();
    // the brace depth outside each open inline module's block
    let mut open: Vec<usize> = Vec::new();
    let mut depth = 0usize;
    for (k, t) in toks.iter().enumerate() {
        out.push(scope.clone());
        match &t.tok {
            Tok::Punct('{') => depth += 1,
            Tok::Punct('}') => {
                depth = depth.saturating_sub(1);
                if open.last() == Some(&depth) {
                    open.pop();
                    scope.pop();
                }
            }
            Tok::Ident(kw) if kw == "mod" => {
                if let (Some(Token { tok: Tok::Ident(name), .. }), Some(b)) =
                    (toks.get(k + 1), toks.get(k + 2))
                    && b.tok == Tok::Punct('{')
                {
                    open.push(depth);
                    scope.push(name.clone());
                }
            }
            _ => {}
        }
    }
    out
}

/// The absolute paths of the path (or `use` tree) starting at `toks[i]`, from the module
/// `base`: `crate` clears it, `self` keeps it, `super` pops a segment, a name pushes one;
/// `{a, b::c}` groups branch. Returns the paths and the index just past the path.
pub fn path_tree(toks: &[Token], mut i: usize, mut base: Vec<String>) -> (Vec<Vec<String>>, usize) {
    let mut out = Vec::new();
    loop {
        match toks.get(i).map(|t| &t.tok) {
            Some(Tok::Ident(s)) => {
                match s.as_str() {
                    "crate" => base.clear(),
                    "self" => {}
                    "super" => {
                        base.pop();
                    }
                    _ => base.push(s.clone()),
                }
                i += 1;
                if !is_path_sep(toks, i) {
                    out.push(base);
                    return (out, i);
                }
                i += 2;
            }
            Some(Tok::Punct('{')) => {
                let end = matching(toks, i).unwrap_or(toks.len().saturating_sub(1));
                let mut k = i + 1;
                while k < end {
                    if toks[k].tok == Tok::Punct(',') {
                        k += 1;
                        continue;
                    }
                    let (paths, next) = path_tree(toks, k, base.clone());
                    out.extend(paths);
                    // skip an alias `as x` and anything else up to the next comma
                    k = next.max(k + 1);
                    while k < end && toks[k].tok != Tok::Punct(',') {
                        k += 1;
                    }
                }
                return (out, end + 1);
            }
            // `*`, generics, or the end: the path so far
            _ => {
                out.push(base);
                return (out, i);
            }
        }
    }
}

/// The strongly connected components of a directed graph (Tarjan), each sorted.
pub fn strongly_connected(edges: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct State<'a> {
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(v: &'a str, st: &mut State<'a>) {
        let n = st.index.len();
        st.index.insert(v, n);
        st.low.insert(v, n);
        st.stack.push(v);
        st.on_stack.insert(v);
        let edges = st.edges;
        for w in edges.get(v).into_iter().flatten() {
            let w = w.as_str();
            if !st.index.contains_key(w) {
                visit(w, st);
                let lw = st.low[w];
                let lv = st.low.get_mut(v).expect("visited");
                if lw < *lv {
                    *lv = lw;
                }
            } else if st.on_stack.contains(w) {
                let iw = st.index[w];
                let lv = st.low.get_mut(v).expect("visited");
                if iw < *lv {
                    *lv = iw;
                }
            }
        }
        if st.low[v] == st.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = st.stack.pop() {
                st.on_stack.remove(w);
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            comp.sort();
            st.out.push(comp);
        }
    }
    let mut st = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in edges.keys() {
        if !st.index.contains_key(v.as_str()) {
            visit(v, &mut st);
        }
    }
    st.out
}
