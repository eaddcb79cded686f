//! The attributes of the Kani mock (see `rigtform-kani-mock`). Each checks
//! the shape of its arguments as Kani documents them and gives the item
//! back; `stub` also makes the compiler check that its two paths are
//! functions of one signature.

use proc_macro::{Delimiter, Spacing, TokenStream, TokenTree};

/// A compile error at the attribute, as tokens.
fn error(message: &str) -> TokenStream {
    format!("compile_error!({message:?});")
        .parse()
        .unwrap_or_default()
}

/// `#[kani::proof]`: no arguments, on a function without parameters.
#[proc_macro_attribute]
pub fn proof(attr: TokenStream, item: TokenStream) -> TokenStream {
    if !attr.is_empty() {
        return error("kani::proof takes no arguments");
    }
    let tokens: Vec<TokenTree> = item.clone().into_iter().collect();
    let after_fn = tokens
        .iter()
        .position(|t| matches!(t, TokenTree::Ident(i) if i.to_string() == "fn"));
    let parameters = after_fn.and_then(|at| tokens.get(at + 2));
    match parameters {
        Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Parenthesis => {
            if !g.stream().is_empty() {
                return error("a kani::proof harness takes no parameters");
            }
        }
        _ => return error("kani::proof goes on a function"),
    }
    // Kani calls the harness; a compile without it sees an unused function.
    let mut out: TokenStream = "#[allow(dead_code)]".parse().unwrap_or_default();
    out.extend(item);
    out
}

/// `#[kani::unwind(n)]`: one integer literal.
#[proc_macro_attribute]
pub fn unwind(attr: TokenStream, item: TokenStream) -> TokenStream {
    let tokens: Vec<TokenTree> = attr.into_iter().collect();
    match tokens.as_slice() {
        [TokenTree::Literal(l)] if l.to_string().parse::<u32>().is_ok() => item,
        _ => error("kani::unwind takes one integer, the unwinding bound"),
    }
}

/// `#[kani::solver(name)]`: one of the SAT solvers Kani ships.
#[proc_macro_attribute]
pub fn solver(attr: TokenStream, item: TokenStream) -> TokenStream {
    let tokens: Vec<TokenTree> = attr.into_iter().collect();
    match tokens.as_slice() {
        [TokenTree::Ident(i)] if ["cadical", "kissat", "minisat"].contains(&&*i.to_string()) => {
            item
        }
        _ => error("kani::solver takes cadical, kissat or minisat"),
    }
}

/// A path as tokens (`a::b::c`), if `tokens` is one.
fn is_path(tokens: &[TokenTree]) -> bool {
    let mut expect_ident = true;
    let mut colons = 0;
    for t in tokens {
        match t {
            TokenTree::Ident(_) if expect_ident => expect_ident = false,
            TokenTree::Punct(p) if !expect_ident && p.as_char() == ':' => {
                colons += 1;
                if colons == 2 {
                    colons = 0;
                    expect_ident = true;
                } else if p.spacing() != Spacing::Joint {
                    return false;
                }
            }
            _ => return false,
        }
    }
    !expect_ident && colons == 0
}

/// `#[kani::stub(original, replacement)]`: two paths; the item comes back
/// with a check that both are functions of one signature (an array of the
/// two coerces to one function pointer type only then).
#[proc_macro_attribute]
pub fn stub(attr: TokenStream, item: TokenStream) -> TokenStream {
    let tokens: Vec<TokenTree> = attr.into_iter().collect();
    let parts: Vec<&[TokenTree]> = tokens
        .split(|t| matches!(t, TokenTree::Punct(p) if p.as_char() == ','))
        .collect();
    let [original, replacement] = parts.as_slice() else {
        return error("kani::stub takes two paths: the function and its stub");
    };
    if !is_path(original) || !is_path(replacement) {
        return error("kani::stub takes two paths: the function and its stub");
    }
    let path = |p: &[TokenTree]| p.iter().cloned().collect::<TokenStream>().to_string();
    let check = format!(
        "const _: () = {{ #[allow(dead_code)] fn same_signature() {{ let _ = [{}, {}]; }} }};",
        path(original),
        path(replacement)
    );
    let mut out: TokenStream = check.parse().unwrap_or_default();
    out.extend(item);
    out
}
