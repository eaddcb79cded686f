//! The attributes of the Kani mock (see `rigtform-kani-mock`). Each checks
//! the shape of its arguments as Kani documents them and gives the item
//! back; `stub` also makes the compiler check that its two paths are
//! functions of one signature, `stub_verified` and `proof_for_contract`
//! that their path exists, and the contract attributes `requires` and
//! `ensures` put a check of their expression's type at the top of the
//! function's body (`bool`; a closure from `&` the result to `bool`), where
//! the function's parameters are in scope, so a contract that names a
//! parameter wrongly, or is not a condition, fails to compile.

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
    harness(item)
}

/// A harness: a function without parameters, marked as used.
fn harness(item: TokenStream) -> TokenStream {
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

/// A function item cut where a contract check goes: its tokens, the index
/// of its body (the last token, a brace group) and its return type (the
/// tokens after `->` up to `where` or the body; `()` without `->`).
struct Function {
    tokens: Vec<TokenTree>,
    body: usize,
    output: TokenStream,
}

/// `item` as a [`Function`], if it is one.
fn function(item: TokenStream) -> Option<Function> {
    let tokens: Vec<TokenTree> = item.into_iter().collect();
    let at_fn = tokens
        .iter()
        .position(|t| matches!(t, TokenTree::Ident(i) if i.to_string() == "fn"))?;
    let parameters = at_fn
        + tokens[at_fn..].iter().position(
            |t| matches!(t, TokenTree::Group(g) if g.delimiter() == Delimiter::Parenthesis),
        )?;
    let body = tokens.len() - 1;
    if !matches!(&tokens[body], TokenTree::Group(g) if g.delimiter() == Delimiter::Brace)
        || body <= parameters
    {
        return None;
    }
    let between = &tokens[parameters + 1..body];
    let output = match between {
        [TokenTree::Punct(minus), TokenTree::Punct(greater), rest @ ..]
            if minus.as_char() == '-' && greater.as_char() == '>' =>
        {
            let end = rest
                .iter()
                .position(|t| matches!(t, TokenTree::Ident(i) if i.to_string() == "where"))
                .unwrap_or(rest.len());
            rest[..end].iter().cloned().collect()
        }
        _ => "()".parse().unwrap_or_default(),
    };
    Some(Function {
        tokens,
        body,
        output,
    })
}

/// The function with `check` (statements) before its body's statements.
fn with_check(f: Function, check: &str) -> TokenStream {
    let Function {
        mut tokens, body, ..
    } = f;
    let mut stream: TokenStream = check.parse().unwrap_or_default();
    if let TokenTree::Group(g) = &tokens[body] {
        stream.extend(g.stream());
        let mut group = proc_macro::Group::new(Delimiter::Brace, stream);
        group.set_span(g.span());
        tokens[body] = TokenTree::Group(group);
    }
    tokens.into_iter().collect()
}

/// `#[kani::requires(condition)]`: the condition, an expression over the
/// function's parameters, must be a `bool`.
#[proc_macro_attribute]
pub fn requires(attr: TokenStream, item: TokenStream) -> TokenStream {
    if attr.is_empty() {
        return error("kani::requires takes a condition");
    }
    let Some(f) = function(item) else {
        return error("kani::requires goes on a function with a body");
    };
    with_check(
        f,
        &format!("let _: &dyn ::core::ops::Fn() -> bool = &|| -> bool {{ {attr} }};"),
    )
}

/// `#[kani::ensures(|result: &T| condition)]`: a closure from a reference
/// to the function's result to `bool`, over the function's parameters.
#[proc_macro_attribute]
pub fn ensures(attr: TokenStream, item: TokenStream) -> TokenStream {
    if attr.is_empty() {
        return error("kani::ensures takes a closure from &result to bool");
    }
    let Some(f) = function(item) else {
        return error("kani::ensures goes on a function with a body");
    };
    let check = format!(
        "let _: &dyn ::core::ops::Fn(&{}) -> bool = &({attr});",
        f.output
    );
    with_check(f, &check)
}

/// A check that `path` (a path, or a qualified path such as
/// `<T as Trait>::f`) names something, before `item`.
fn with_path_check(what: &str, path: TokenStream, item: TokenStream) -> TokenStream {
    let tokens: Vec<TokenTree> = path.clone().into_iter().collect();
    if tokens.is_empty()
        || tokens
            .iter()
            .any(|t| matches!(t, TokenTree::Punct(p) if p.as_char() == ','))
    {
        return error(&format!(
            "{what} takes one path, the function with the contract"
        ));
    }
    let check = format!(
        "const _: () = {{ #[allow(dead_code)] fn the_contract_target_exists() {{ let _ = {path}; }} }};"
    );
    let mut out: TokenStream = check.parse().unwrap_or_default();
    out.extend(item);
    out
}

/// `#[kani::proof_for_contract(path)]`: a harness (no parameters) for the
/// contract of the function at `path`.
#[proc_macro_attribute]
pub fn proof_for_contract(attr: TokenStream, item: TokenStream) -> TokenStream {
    with_path_check("kani::proof_for_contract", attr, harness(item))
}

/// `#[kani::stub_verified(path)]`: on a harness, the function at `path`
/// replaced by its contract.
#[proc_macro_attribute]
pub fn stub_verified(attr: TokenStream, item: TokenStream) -> TokenStream {
    with_path_check("kani::stub_verified", attr, item)
}
