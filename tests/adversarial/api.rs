//! The public API of a workspace crate, read from its source with `syn`.
//!
//! The adversarial suite must grow with the API: a public function without a case is a test
//! failure. This module walks `crates/<name>/src/lib.rs` and the module files it declares
//! (`mod x;` → `x.rs` or `x/mod.rs`, `#[path]` honoured), and lists every function a user of
//! the crate can call:
//!
//! * a free `pub fn` in a module whose every segment is `pub mod` is named
//!   `module::function` (`attitude::jacobian_left`); one in a private module is public only if
//!   a `pub use` re-exports it, and is then named by its bare name (`wrap_angle`);
//! * a `pub fn` in an inherent `impl Type` is named `Type::method` when `Type` is public by
//!   the same rule (methods of trait impls are the trait's, not the type's API);
//! * a method declared in a public trait is named `Trait::method`.
//!
//! `pub(crate)`, `pub(super)` and `pub(in …)` are not public; `#[cfg(test)]` modules and
//! `#[doc(hidden)]` items are skipped.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use syn::{Attribute, ImplItem, Item, TraitItem, UseTree, Visibility};

/// One public function: its qualified name and the file that defines it (relative to the
/// crate's `src/`).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct PublicFn {
    /// `Type::method`, `module::function` or `function`.
    pub name: String,
    /// The defining file, relative to `src/` (`attitude/rates.rs`).
    pub file: String,
}

#[derive(Default)]
struct Walk {
    /// Leaf names re-exported by some `pub use` (items and modules).
    reexported: BTreeSet<String>,
    /// Modules re-exported by a glob `pub use module::*`.
    glob_modules: BTreeSet<String>,
    /// Free functions: (name, module path, module public?, file).
    free: Vec<(String, Vec<String>, bool, String)>,
    /// Inherent methods: (type, method, file).
    methods: Vec<(String, String, String)>,
    /// Public trait methods: (trait, method, file, trait public-by-path?).
    trait_methods: Vec<(String, String, String, bool)>,
    /// Types declared `pub`: name → declared in a public module path?
    types: BTreeMap<String, bool>,
}

fn is_pub(v: &Visibility) -> bool {
    matches!(v, Visibility::Public(_))
}

fn skipped(attrs: &[Attribute]) -> bool {
    attrs.iter().any(|a| {
        let p = a.path();
        if p.is_ident("cfg") {
            let s = a.meta.to_token_stream_string();
            return s.contains("test");
        }
        if p.is_ident("doc") {
            let s = a.meta.to_token_stream_string();
            return s.contains("hidden");
        }
        false
    })
}

trait MetaString {
    fn to_token_stream_string(&self) -> String;
}
impl MetaString for syn::Meta {
    fn to_token_stream_string(&self) -> String {
        quote_meta(self)
    }
}

fn quote_meta(m: &syn::Meta) -> String {
    match m {
        syn::Meta::Path(p) => path_string(p),
        syn::Meta::List(l) => format!("{}({})", path_string(&l.path), l.tokens),
        syn::Meta::NameValue(nv) => path_string(&nv.path),
    }
}

fn path_string(p: &syn::Path) -> String {
    p.segments.iter().map(|s| s.ident.to_string()).collect::<Vec<_>>().join("::")
}

fn path_attr(attrs: &[Attribute]) -> Option<String> {
    attrs.iter().find_map(|a| match &a.meta {
        syn::Meta::NameValue(nv) if nv.path.is_ident("path") => match &nv.value {
            syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(s), .. }) => Some(s.value()),
            _ => None,
        },
        _ => None,
    })
}

fn collect_use(tree: &UseTree, prefix: &mut Vec<String>, walk: &mut Walk) {
    match tree {
        UseTree::Path(p) => {
            prefix.push(p.ident.to_string());
            collect_use(&p.tree, prefix, walk);
            prefix.pop();
        }
        UseTree::Name(n) => {
            walk.reexported.insert(n.ident.to_string());
        }
        UseTree::Rename(r) => {
            walk.reexported.insert(r.ident.to_string());
        }
        UseTree::Glob(_) => {
            if let Some(last) = prefix.last() {
                walk.glob_modules.insert(last.clone());
            }
        }
        UseTree::Group(g) => {
            for t in &g.items {
                collect_use(t, prefix, walk);
            }
        }
    }
}

fn self_type_name(ty: &syn::Type) -> Option<String> {
    match ty {
        syn::Type::Path(p) => p.path.segments.last().map(|s| s.ident.to_string()),
        _ => None,
    }
}

impl Walk {
    fn items(
        &mut self,
        items: &[Item],
        module: &[String],
        module_public: bool,
        dir: &Path,
        file: &str,
        src: &Path,
    ) {
        for item in items {
            match item {
                Item::Fn(f) if is_pub(&f.vis) && !skipped(&f.attrs) => {
                    self.free.push((
                        f.sig.ident.to_string(),
                        module.to_vec(),
                        module_public,
                        file.to_string(),
                    ));
                }
                Item::Struct(s) if is_pub(&s.vis) => {
                    self.types.insert(s.ident.to_string(), module_public);
                }
                Item::Enum(e) if is_pub(&e.vis) => {
                    self.types.insert(e.ident.to_string(), module_public);
                }
                Item::Type(t) if is_pub(&t.vis) => {
                    self.types.insert(t.ident.to_string(), module_public);
                }
                Item::Trait(t) if is_pub(&t.vis) && !skipped(&t.attrs) => {
                    self.types.insert(t.ident.to_string(), module_public);
                    for ti in &t.items {
                        if let TraitItem::Fn(f) = ti
                            && !skipped(&f.attrs)
                        {
                            self.trait_methods.push((
                                t.ident.to_string(),
                                f.sig.ident.to_string(),
                                file.to_string(),
                                module_public,
                            ));
                        }
                    }
                }
                Item::Impl(imp) if imp.trait_.is_none() && !skipped(&imp.attrs) => {
                    let Some(ty) = self_type_name(&imp.self_ty) else { continue };
                    for ii in &imp.items {
                        if let ImplItem::Fn(f) = ii
                            && is_pub(&f.vis)
                            && !skipped(&f.attrs)
                        {
                            self.methods.push((ty.clone(), f.sig.ident.to_string(), file.into()));
                        }
                    }
                }
                Item::Use(u) if is_pub(&u.vis) => collect_use(&u.tree, &mut Vec::new(), self),
                Item::Mod(m) if !skipped(&m.attrs) => {
                    let name = m.ident.to_string();
                    let public = module_public && is_pub(&m.vis);
                    let mut path = module.to_vec();
                    path.push(name.clone());
                    if let Some((_, inline)) = &m.content {
                        self.items(inline, &path, public, &dir.join(&name), file, src);
                        continue;
                    }
                    let candidates = match path_attr(&m.attrs) {
                        // a #[path] outside inline modules is relative to the declaring file's folder
                        Some(p) => vec![src.join(file).parent().map_or_else(|| dir.join(&p), |d| d.join(&p))],
                        None => vec![dir.join(format!("{name}.rs")), dir.join(&name).join("mod.rs")],
                    };
                    let Some(found) = candidates.into_iter().find(|p| p.exists()) else {
                        panic!("module {name} declared in {file} has no file");
                    };
                    let child_dir = if found.ends_with("mod.rs") {
                        found.parent().unwrap().to_path_buf()
                    } else {
                        dir.join(&name)
                    };
                    let rel = found.strip_prefix(src).unwrap().to_string_lossy().into_owned();
                    let parsed = parse(&found);
                    self.items(&parsed.items, &path, public, &child_dir, &rel, src);
                }
                _ => {}
            }
        }
    }
}

fn parse(path: &Path) -> syn::File {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    syn::parse_file(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The workspace root (this test binary's package root).
pub fn workspace_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every public function of `crates/<krate>`, sorted by name.
pub fn public_functions(krate: &str) -> Vec<PublicFn> {
    let src = workspace_root().join("crates").join(krate).join("src");
    let lib = src.join("lib.rs");
    let mut walk = Walk::default();
    let parsed = parse(&lib);
    walk.items(&parsed.items, &[], true, &src, "lib.rs", &src);

    let type_public = |ty: &str, walk: &Walk| {
        walk.types.get(ty).is_some_and(|&in_pub_module| in_pub_module) || walk.reexported.contains(ty)
    };
    let mut out = BTreeSet::new();
    for (name, module, public, file) in &walk.free {
        let glob = module.last().is_some_and(|m| walk.glob_modules.contains(m));
        if *public && !module.is_empty() {
            out.insert(PublicFn { name: format!("{}::{name}", module.join("::")), file: file.clone() });
        } else if *public || walk.reexported.contains(name) || glob {
            out.insert(PublicFn { name: name.clone(), file: file.clone() });
        }
    }
    for (ty, method, file) in &walk.methods {
        if type_public(ty, &walk) {
            out.insert(PublicFn { name: format!("{ty}::{method}"), file: file.clone() });
        }
    }
    for (tr, method, file, _) in &walk.trait_methods {
        if type_public(tr, &walk) {
            out.insert(PublicFn { name: format!("{tr}::{method}"), file: file.clone() });
        }
    }
    out.into_iter().collect()
}
