//! Emitted tokens as readable Rust source, for the files a build script
//! writes: items one per line, doc attributes as `///` comments, bodies
//! indented. It prints the tokens the macros return; it never builds text
//! of its own.

use proc_macro2::{Delimiter, Spacing, TokenStream, TokenTree};
use std::string::{String, ToString};
use std::vec::Vec;

/// The source of `tokens`, a sequence of items.
pub fn print(tokens: TokenStream) -> String {
    let mut out = String::new();
    items(&mut out, tokens, 0);
    out
}

/// Prints items: each attribute and each statement on its own line, braces
/// opening an indented block.
fn items(out: &mut String, tokens: TokenStream, depth: usize) {
    let mut line: Vec<TokenTree> = Vec::new();
    let mut trees = tokens.into_iter().peekable();
    while let Some(tree) = trees.next() {
        match &tree {
            TokenTree::Punct(p) if p.as_char() == '#' && line.is_empty() => {
                if let Some(TokenTree::Group(attr)) = trees.next() {
                    indent(out, depth);
                    attribute(out, attr.stream());
                    out.push('\n');
                }
            }
            TokenTree::Group(g) if g.delimiter() == Delimiter::Brace => {
                indent(out, depth);
                inline(out, &line);
                out.push_str(" {\n");
                items(out, g.stream(), depth + 1);
                indent(out, depth);
                out.push_str("}\n");
                line.clear();
            }
            TokenTree::Punct(p) if p.as_char() == ';' => {
                indent(out, depth);
                inline(out, &line);
                out.push_str(";\n");
                line.clear();
            }
            _ => line.push(tree),
        }
    }
    if !line.is_empty() {
        indent(out, depth);
        inline(out, &line);
        out.push('\n');
    }
}

fn indent(out: &mut String, depth: usize) {
    for _ in 0..depth {
        out.push_str("    ");
    }
}

/// `#[doc = "text"]` as `///text`; any other attribute as written.
fn attribute(out: &mut String, attr: TokenStream) {
    let trees: Vec<TokenTree> = attr.clone().into_iter().collect();
    if let [
        TokenTree::Ident(name),
        TokenTree::Punct(eq),
        TokenTree::Literal(text),
    ] = &trees[..]
    {
        let text = text.to_string();
        if name == "doc" && eq.as_char() == '=' && !text.contains('\\') {
            if let Some(doc) = text.strip_prefix('"').and_then(|t| t.strip_suffix('"')) {
                out.push_str("///");
                out.push_str(doc);
                return;
            }
        }
    }
    out.push_str("#[");
    inline(out, &trees);
    out.push(']');
}

/// Tokens on one line, spaced as `rustfmt` spaces them.
fn inline(out: &mut String, trees: &[TokenTree]) {
    let mut space = false;
    let mut after_ident = false;
    // The first `:` of a path's `::`.
    let mut path = false;
    for tree in trees {
        match tree {
            TokenTree::Punct(p) => {
                let c = p.as_char();
                let joint = p.spacing() == Spacing::Joint;
                // A negative number's sign after `=` or `,` (a literal's
                // `-` reaches the printer as its own token), a path's
                // leading `::` after `:` or `=`.
                if c == '=' || (space && (c == '-' || (c == ':' && joint && !after_ident))) {
                    out.push(' ');
                }
                out.push(c);
                let closes_path = path && c == ':';
                path = c == ':' && joint;
                space = matches!(c, ',' | ':' | '=' | ';') && !joint && !closes_path;
                after_ident = false;
                continue;
            }
            TokenTree::Group(g) => {
                // A call or an attribute's arguments hug their name.
                if space && !(after_ident && g.delimiter() == Delimiter::Parenthesis) {
                    out.push(' ');
                }
                let (open, close) = match g.delimiter() {
                    Delimiter::Parenthesis => ("(", ")"),
                    Delimiter::Bracket => ("[", "]"),
                    Delimiter::Brace => ("{ ", " }"),
                    Delimiter::None => ("", ""),
                };
                out.push_str(open);
                let inner: Vec<TokenTree> = g.stream().into_iter().collect();
                inline(out, &inner);
                out.push_str(close);
                space = true;
            }
            other => {
                if space {
                    out.push(' ');
                }
                out.push_str(&other.to_string());
                space = true;
            }
        }
        after_ident = matches!(tree, TokenTree::Ident(_));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    #[test]
    fn items_print_as_rustfmt_would() {
        let minus_one = proc_macro2::Literal::i32_unsuffixed(-1);
        let tokens = quote! {
            #[doc = " A module."]
            #[doc = ""]
            #[allow(dead_code)]
            pub mod m {
                pub static P: [u16; 3] = [3u16, 2, 1];
                pub static S: [(u16, u16); 1] = [(9u16, 3u16)];
                pub const X: f64 = 0.5;
                pub const O: i32 = #minus_one;
                pub const R: ::a::B<'static, u16, 5> = ::a::B::new(&P, O);
            }
        };
        assert_eq!(
            print(tokens),
            "/// A module.\n///\n#[allow(dead_code)]\npub mod m {\n    \
             pub static P: [u16; 3] = [3u16, 2, 1];\n    \
             pub static S: [(u16, u16); 1] = [(9u16, 3u16)];\n    \
             pub const X: f64 = 0.5;\n    \
             pub const O: i32 = -1;\n    \
             pub const R: ::a::B<'static, u16, 5> = ::a::B::new(&P, O);\n}\n"
        );
    }
}
