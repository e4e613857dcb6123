//! `#[transcript::task]`: the two faces of a task function, the one that
//! records a call of the student's body and the one that replays it (see
//! the `transcript` crate for why).
//!
//! What the expansion understands of a signature:
//!
//! | parameter                                  | recorded                      |
//! |--------------------------------------------|-------------------------------|
//! | `impl Fn(A, ..) -> R` (`FnMut`, `FnOnce`)  | every call, its arguments     |
//! | `&impl Fn..`, `&mut impl FnMut..`, `&dyn ..`, `&mut dyn ..` | as above |
//! | `&mut T`, `&mut self`                      | what changed, when it ends    |
//! | anything else (values, `&T`, `self`)       | nothing: the test passed it   |
//!
//! and the return value, whose type (or, for `&'static T`, `T`) must be
//! `transcript::Record` and `transcript::Replay` (a type marked
//! `#[transcript::evidence]`, or one the `transcript` crate knows), as
//! must every callback argument (a `&T` argument: `T`; `&[T]`: `Vec<T>`)
//! and every `&mut T`.
//! Under `cfg(transcript_replay)` the body is dropped unread.

use proc_macro::TokenStream;
use proc_macro2::TokenStream as Tokens;
use quote::{format_ident, quote};
use syn::spanned::Spanned as _;
use syn::{
    FnArg, Ident, ItemFn, Pat, PathArguments, ReturnType, Type, TypeParamBound, parse_macro_input,
    parse_quote,
};

/// The error for arguments given to `#[transcript::<name>]`, which takes
/// none.
fn arguments_given(attr: TokenStream, name: &str) -> Option<TokenStream> {
    (!attr.is_empty()).then(|| {
        let message = format!("`#[transcript::{name}]` takes no arguments");
        syn::Error::new(Tokens::from(attr).span(), message)
            .to_compile_error()
            .into()
    })
}

/// Marks a function a task asks for: in the student's crate its calls are
/// recorded while the grader asks for it; in the grader's replay build
/// they are replayed from the record (see the `transcript` crate).
#[proc_macro_attribute]
pub fn task(attr: TokenStream, item: TokenStream) -> TokenStream {
    if let Some(error) = arguments_given(attr, "task") {
        return error;
    }
    let function = parse_macro_input!(item as ItemFn);
    expand(function).unwrap_or_else(|error| error.to_compile_error().into())
}

/// Marks a type whose values cross between a task function and its test:
/// implements `transcript::Record` and `transcript::Replay` in the type's
/// own crate (see the `transcript` crate's `evidence` module for why
/// there): a struct field by field, an enum as its variant's number and
/// then that variant's fields. Every field's type must be evidence too; a
/// type generic over types (`CurvePoint<P>`) gets both for every `P` that
/// has them (compiled where `P` is chosen).
#[proc_macro_attribute]
pub fn evidence(attr: TokenStream, item: TokenStream) -> TokenStream {
    if let Some(error) = arguments_given(attr, "evidence") {
        return error;
    }
    let input = parse_macro_input!(item as syn::DeriveInput);
    // A type may be generic over types (a point type: `CurvePoint<P>`),
    // each then bound by the trait implemented.
    if !input
        .generics
        .params
        .iter()
        .all(|param| matches!(param, syn::GenericParam::Type(_)))
    {
        return syn::Error::new(
            input.generics.span(),
            "`#[transcript::evidence]` takes a type generic over types only",
        )
        .to_compile_error()
        .into();
    }
    let name = &input.ident;
    let generics = Generics::of(&input.generics);
    let expanded = match &input.data {
        syn::Data::Struct(data) => evidence_struct(name, &generics, &data.fields),
        syn::Data::Enum(data) => evidence_enum(name, &generics, data),
        syn::Data::Union(_) => {
            return syn::Error::new(
                input.span(),
                "`#[transcript::evidence]` takes a struct or an enum",
            )
            .to_compile_error()
            .into();
        }
    };
    quote! {
        #input
        #expanded
    }
    .into()
}

/// The generics of an evidence impl: the type's own, each type parameter
/// bound by the trait implemented.
struct Generics {
    record: syn::Generics,
    replay: syn::Generics,
    ty: syn::Generics,
}

impl Generics {
    fn of(generics: &syn::Generics) -> Generics {
        let bounded = |bound: Tokens| {
            let mut generics = generics.clone();
            for param in generics.type_params_mut() {
                param.bounds.push(parse_quote! { #bound });
            }
            generics
        };
        Generics {
            record: bounded(quote! { ::transcript::Record }),
            replay: bounded(quote! { ::transcript::Replay }),
            ty: generics.clone(),
        }
    }

    /// `impl<..> ::transcript::Record for Name<..> where ..`
    fn record_impl(&self, name: &Ident) -> Tokens {
        let (generics, _, bounds) = self.record.split_for_impl();
        let (_, ty, _) = self.ty.split_for_impl();
        quote! { impl #generics ::transcript::Record for #name #ty #bounds }
    }

    /// `impl<..> ::transcript::Replay for Name<..> where ..`
    fn replay_impl(&self, name: &Ident) -> Tokens {
        let (generics, _, bounds) = self.replay.split_for_impl();
        let (_, ty, _) = self.ty.split_for_impl();
        quote! { impl #generics ::transcript::Replay for #name #ty #bounds }
    }
}

/// The members of `fields` (names or indices), and the bindings a pattern
/// gives them.
fn members(fields: &syn::Fields) -> (Vec<syn::Member>, Vec<Ident>) {
    fields
        .iter()
        .enumerate()
        .map(|(index, field)| match &field.ident {
            Some(ident) => (
                syn::Member::Named(ident.clone()),
                format_ident!("__transcript_{ident}"),
            ),
            None => (
                syn::Member::Unnamed(syn::Index::from(index)),
                format_ident!("__transcript_field{index}"),
            ),
        })
        .unzip()
}

/// The expression that reads a value of `fields`' shape, `path` its
/// constructor (`Self` or `Self::Variant`).
fn build(path: &Tokens, fields: &syn::Fields) -> Tokens {
    let (members, _) = members(fields);
    let types = fields.iter().map(|field| &field.ty);
    match fields {
        syn::Fields::Named(_) => {
            quote! { #path { #(#members: <#types as ::transcript::Replay>::replay(input)?,)* } }
        }
        syn::Fields::Unnamed(_) => {
            quote! { #path(#(<#types as ::transcript::Replay>::replay(input)?,)*) }
        }
        syn::Fields::Unit => quote! { #path },
    }
}

/// A struct, field by field, each through its own type's `Record`
/// (optimised where that type lives); its changes field by field too, so a
/// struct of canvases records only the pixels written.
fn evidence_struct(name: &Ident, generics: &Generics, fields: &syn::Fields) -> Tokens {
    let (members, _) = members(fields);
    let build = build(&quote! { Self }, fields);
    let record_impl = generics.record_impl(name);
    let replay_impl = generics.replay_impl(name);
    quote! {
        #record_impl {
            fn record(&self, out: &mut ::std::vec::Vec<u8>) {
                #(::transcript::Record::record(&self.#members, out);)*
            }

            fn begin_changes(&mut self) {
                #(::transcript::Record::begin_changes(&mut self.#members);)*
            }

            fn record_changes(&mut self, out: &mut ::std::vec::Vec<u8>) {
                #(::transcript::Record::record_changes(&mut self.#members, out);)*
            }
        }

        #replay_impl {
            fn replay(input: &mut &[u8]) -> ::core::result::Result<Self, ::std::string::String> {
                ::core::result::Result::Ok(#build)
            }

            fn replay_changes(
                &mut self,
                input: &mut &[u8],
            ) -> ::core::result::Result<(), ::std::string::String> {
                #(::transcript::Replay::replay_changes(&mut self.#members, input)?;)*
                ::core::result::Result::Ok(())
            }
        }
    }
}

/// An enum: the variant's number (its place in the declaration), then its
/// fields as a struct's.
fn evidence_enum(name: &Ident, generics: &Generics, data: &syn::DataEnum) -> Tokens {
    let record_impl = generics.record_impl(name);
    let replay_impl = generics.replay_impl(name);
    let mut records = Vec::new();
    let mut replays = Vec::new();
    for (index, variant) in data.variants.iter().enumerate() {
        let tag = u32::try_from(index).unwrap_or(u32::MAX);
        let ident = &variant.ident;
        let (members, bindings) = members(&variant.fields);
        let pattern = match &variant.fields {
            syn::Fields::Named(_) => quote! { Self::#ident { #(#members: #bindings),* } },
            syn::Fields::Unnamed(_) => quote! { Self::#ident(#(#bindings),*) },
            syn::Fields::Unit => quote! { Self::#ident },
        };
        records.push(quote! {
            #pattern => {
                ::transcript::Record::record(&#tag, out);
                #(::transcript::Record::record(#bindings, out);)*
            }
        });
        let build = build(&quote! { Self::#ident }, &variant.fields);
        replays.push(quote! { #tag => #build, });
    }
    let unknown = format!("no variant {{}} of `{name}`");
    quote! {
        #record_impl {
            fn record(&self, out: &mut ::std::vec::Vec<u8>) {
                match self {
                    #(#records)*
                }
            }
        }

        #replay_impl {
            fn replay(input: &mut &[u8]) -> ::core::result::Result<Self, ::std::string::String> {
                ::core::result::Result::Ok(match <u32 as ::transcript::Replay>::replay(input)? {
                    #(#replays)*
                    tag => {
                        return ::core::result::Result::Err(::std::format!(#unknown, tag));
                    }
                })
            }
        }
    }
}

/// A callback parameter: how it is passed and what its arguments are.
struct Callback {
    /// `&` or `&mut` in front of the `impl`/`dyn` (None: by value).
    by_ref: Option<bool>,
    /// Its argument types.
    arguments: Vec<Type>,
    /// Its return type.
    output: Type,
    /// `Fn`, `FnMut` or `FnOnce`.
    kind: Ident,
    /// Written `dyn Fn..` rather than `impl Fn..`.
    dynamic: bool,
}

/// What the expansion does with one parameter.
enum Role {
    /// A callback: every call recorded.
    Callback(Callback),
    /// `&mut T`: its final value recorded.
    Mutated(Type),
    /// A value the test passed in: nothing recorded.
    Input,
}

struct Parameter {
    /// The name it has in the expanded signature.
    name: Ident,
    /// The pattern the body binds, when the signature's was not a plain name.
    pattern: Option<Pat>,
    role: Role,
}

fn expand(mut function: ItemFn) -> syn::Result<TokenStream> {
    let sig = &function.sig;
    if sig.asyncness.is_some() || sig.constness.is_some() || sig.unsafety.is_some() {
        return Err(syn::Error::new(
            sig.span(),
            "`#[transcript::task]` takes a plain `fn` (not async, const or unsafe)",
        ));
    }
    let name = &sig.ident;
    let label = quote! { ::core::concat!(::core::module_path!(), "::", ::core::stringify!(#name)) };
    let mut receiver_mutated = false;
    let mut parameters = Vec::new();
    for (index, input) in function.sig.inputs.iter_mut().enumerate() {
        match input {
            FnArg::Receiver(receiver) => {
                receiver_mutated = receiver.reference.is_some() && receiver.mutability.is_some();
            }
            FnArg::Typed(typed) => {
                let role = role(&typed.ty)?;
                let (name, pattern) = match &*typed.pat {
                    Pat::Ident(ident) if ident.subpat.is_none() && ident.by_ref.is_none() => {
                        let pattern = ident.mutability.is_some().then(|| (*typed.pat).clone());
                        (ident.ident.clone(), pattern)
                    }
                    other => (
                        format_ident!("__transcript_arg{index}"),
                        Some(other.clone()),
                    ),
                };
                *typed.pat = parse_quote! { #name };
                parameters.push(Parameter {
                    name,
                    pattern,
                    role,
                });
            }
        }
    }
    let output = match &function.sig.output {
        ReturnType::Default => parse_quote! { () },
        ReturnType::Type(_, ty) => (**ty).clone(),
    };
    if let Type::ImplTrait(_) = output {
        return Err(syn::Error::new(
            output.span(),
            "`#[transcript::task]` cannot record an `impl Trait` return value",
        ));
    }
    let record = record(&function, &parameters, receiver_mutated, &output, &label);
    let replay = replay(&parameters, receiver_mutated, &output, &label)?;
    let ItemFn {
        attrs, vis, sig, ..
    } = &function;
    Ok(quote! {
        #[cfg(not(transcript_replay))]
        #(#attrs)* #vis #sig #record

        #[cfg(transcript_replay)]
        #(#attrs)* #vis #sig #replay
    }
    .into())
}

/// The recording body: the student's body, its callbacks wrapped.
fn record(
    function: &ItemFn,
    parameters: &[Parameter],
    receiver_mutated: bool,
    output: &Type,
    label: &Tokens,
) -> Tokens {
    let mut prologue = Vec::new();
    let mut mutated_names = Vec::new();
    for (position, parameter) in parameters.iter().enumerate() {
        let name = &parameter.name;
        let position = u32::try_from(position).unwrap_or(u32::MAX);
        match &parameter.role {
            Role::Callback(callback) => {
                let arguments: Vec<Ident> = (0..callback.arguments.len())
                    .map(|i| format_ident!("__transcript_x{i}"))
                    .collect();
                let types = &callback.arguments;
                let ret = &callback.output;
                let inner = format_ident!("__transcript_inner{position}");
                let wrapper = quote! {
                    move |#(#arguments: #types),*| -> #ret {
                        __transcript_recording.callback(
                            #position,
                            (#(#arguments,)*),
                            |__transcript_arguments, __transcript_out| {
                                let (#(#arguments,)*) = __transcript_arguments;
                                #(::transcript::Record::record(#arguments, __transcript_out);)*
                            },
                            |(#(#arguments,)*)| (#inner)(#(#arguments),*),
                        )
                    }
                };
                prologue.push(match callback.by_ref {
                    None => quote! {
                        #[allow(unused_mut)]
                        let mut #inner = #name;
                        let #name = #wrapper;
                    },
                    // Passed on as a reference to `&dyn Fn..`, whatever the
                    // caller's closure: a body that passes its callback on to
                    // a call of itself (a recursive walk) then instantiates
                    // itself with that one type rather than with a wrapper
                    // of a wrapper of ... for ever.
                    Some(mutable) => {
                        let wrapped = format_ident!("__transcript_wrapped{position}");
                        let erased = format_ident!("__transcript_erased{position}");
                        let kind = &callback.kind;
                        let borrow = if mutable {
                            quote! { &mut }
                        } else {
                            quote! { & }
                        };
                        let pass = if callback.dynamic {
                            quote! { #erased }
                        } else {
                            quote! { #borrow #erased }
                        };
                        quote! {
                            #[allow(unused_mut)]
                            let mut #inner = #name;
                            #[allow(unused_mut)]
                            let mut #wrapped = #wrapper;
                            #[allow(unused_mut)]
                            let mut #erased: #borrow dyn #kind(#(#types),*) -> #ret =
                                #borrow #wrapped;
                            let #name = #pass;
                        }
                    }
                });
            }
            Role::Mutated(_) => mutated_names.push(name.clone()),
            Role::Input => {}
        }
    }
    let bindings = parameters.iter().filter_map(|parameter| {
        let name = &parameter.name;
        parameter
            .pattern
            .as_ref()
            .map(|pattern| quote! { let #pattern = #name; })
    });
    // `&mut` parameters reach the body as arguments of its closure, so
    // that the body may move them and the final values can still be read.
    let mutated_types: Vec<Tokens> = parameters
        .iter()
        .filter_map(|parameter| match &parameter.role {
            Role::Mutated(ty) => Some(quote! { &mut #ty }),
            _ => None,
        })
        .collect();
    let receiver = receiver_mutated
        .then(|| quote! { ::transcript::Record::record_changes(&mut *self, __transcript_out); });
    let begin_receiver =
        receiver_mutated.then(|| quote! { ::transcript::Record::begin_changes(&mut *self); });
    let block = &function.block;
    quote! {{
        let __transcript_call = ::transcript::__private::Call::enter(#label);
        let __transcript_recording = __transcript_call.recording();
        if __transcript_recording.is_on() {
            #begin_receiver
            #(::transcript::Record::begin_changes(&mut *#mutated_names);)*
        }
        #(#prologue)*
        #[allow(unused_mut)]
        let mut __transcript_body = |#(#mutated_names: #mutated_types),*| -> #output {
            #(#bindings)*
            #block
        };
        let __transcript_value =
            __transcript_call.run(|| __transcript_body(#(&mut *#mutated_names),*));
        __transcript_call.finish(&mut |__transcript_out: &mut ::std::vec::Vec<u8>| {
            ::transcript::Record::record(&__transcript_value, __transcript_out);
            #receiver
            #(::transcript::Record::record_changes(&mut *#mutated_names, __transcript_out);)*
        });
        __transcript_value
    }}
}

/// The replaying body: the recorded calls of the callbacks, then the
/// recorded values.
fn replay(
    parameters: &[Parameter],
    receiver_mutated: bool,
    output: &Type,
    label: &Tokens,
) -> syn::Result<Tokens> {
    let mut unused = Vec::new();
    let mut prologue = Vec::new();
    let mut arms = Vec::new();
    let mut mutated = Vec::new();
    for (position, parameter) in parameters.iter().enumerate() {
        let name = &parameter.name;
        let position = u32::try_from(position).unwrap_or(u32::MAX);
        match &parameter.role {
            Role::Callback(callback) => {
                let mut decoded_types = Vec::new();
                let mut passed = Vec::new();
                for (i, ty) in callback.arguments.iter().enumerate() {
                    let value = format_ident!("__transcript_x{i}");
                    let (decoded, pass) = decoded(ty, &value)?;
                    decoded_types.push(decoded);
                    passed.push(pass);
                }
                let values =
                    (0..callback.arguments.len()).map(|i| format_ident!("__transcript_x{i}"));
                let call = match callback.by_ref {
                    None => {
                        prologue.push(quote! {
                            #[allow(unused_mut)]
                            let mut #name = #name;
                        });
                        quote! { (#name)(#(#passed),*) }
                    }
                    Some(_) => quote! { (*#name)(#(#passed),*) },
                };
                arms.push(quote! {
                    ::transcript::__private::Step::Callback(#position, __transcript_bytes) => {
                        let mut __transcript_input: &[u8] = &__transcript_bytes[..];
                        #(
                            #[allow(unused_mut)]
                            let mut #values: #decoded_types =
                                __transcript.decode(&mut __transcript_input);
                        )*
                        __transcript.done(__transcript_input);
                        let _ = #call;
                    }
                });
            }
            Role::Mutated(ty) => mutated.push((name.clone(), ty.clone())),
            Role::Input => unused.push(name.clone()),
        }
    }
    let (returned, leak) = match output {
        Type::Reference(reference)
            if reference
                .lifetime
                .as_ref()
                .is_some_and(|l| l.ident == "static")
                && reference.mutability.is_none() =>
        {
            ((*reference.elem).clone(), true)
        }
        Type::Reference(_) => {
            return Err(syn::Error::new(
                output.span(),
                "`#[transcript::task]` can replay a returned reference only if it is `&'static`",
            ));
        }
        other => (other.clone(), false),
    };
    // The `&mut` values are brought to what the student's call left of
    // them, each from its own value before the call.
    let mut changes = Vec::new();
    if receiver_mutated {
        changes.push(quote! { __transcript.changes(&mut *self, &mut __transcript_input); });
    }
    for (name, _) in &mutated {
        changes.push(quote! { __transcript.changes(&mut *#name, &mut __transcript_input); });
    }
    let value = if leak {
        quote! { ::transcript::__private::leak(__transcript_value) }
    } else {
        quote! { __transcript_value }
    };
    Ok(quote! {{
        let _ = (#(&#unused,)*);
        #(#prologue)*
        let __transcript = ::transcript::__private::Replaying::enter(#label);
        loop {
            match __transcript.next() {
                #(#arms)*
                ::transcript::__private::Step::Callback(__transcript_other, _) => {
                    __transcript.no_such_callback(__transcript_other)
                }
                ::transcript::__private::Step::Return(__transcript_bytes) => {
                    let mut __transcript_input: &[u8] = &__transcript_bytes;
                    let __transcript_value: #returned =
                        __transcript.decode(&mut __transcript_input);
                    #(#changes)*
                    __transcript.done(__transcript_input);
                    return #value;
                }
                ::transcript::__private::Step::Panic(__transcript_message) => {
                    ::std::panic!("{}", __transcript_message)
                }
            }
        }
    }})
}

/// The type a recorded callback argument of type `ty` is decoded as, and
/// the expression that passes the decoded `value` on.
fn decoded(ty: &Type, value: &Ident) -> syn::Result<(Tokens, Tokens)> {
    Ok(match ty {
        Type::Reference(reference) => {
            let borrow = if reference.mutability.is_some() {
                quote! { &mut }
            } else {
                quote! { & }
            };
            match &*reference.elem {
                Type::Slice(slice) => {
                    let elem = &slice.elem;
                    (
                        quote! { ::std::vec::Vec<#elem> },
                        quote! { #borrow #value[..] },
                    )
                }
                Type::Path(path) if path.path.is_ident("str") => (
                    quote! { ::std::string::String },
                    quote! { #borrow #value[..] },
                ),
                Type::Reference(_) => {
                    return Err(syn::Error::new(
                        ty.span(),
                        "`#[transcript::task]` cannot replay a callback argument that is a reference to a reference",
                    ));
                }
                elem => (quote! { #elem }, quote! { #borrow #value }),
            }
        }
        other => (quote! { #other }, quote! { #value }),
    })
}

/// What a parameter of type `ty` is to the recording.
fn role(ty: &Type) -> syn::Result<Role> {
    if let Some(callback) = callback(ty, None)? {
        return Ok(Role::Callback(callback));
    }
    if let Type::Reference(reference) = ty {
        if let Some(callback) = callback(&reference.elem, Some(reference.mutability.is_some()))? {
            return Ok(Role::Callback(callback));
        }
        if reference.mutability.is_some() {
            return Ok(Role::Mutated((*reference.elem).clone()));
        }
    }
    Ok(Role::Input)
}

/// `ty` as a callback (`impl Fn..` or `dyn Fn..`), if it is one.
fn callback(ty: &Type, by_ref: Option<bool>) -> syn::Result<Option<Callback>> {
    let (bounds, dynamic) = match ty {
        Type::ImplTrait(ty) => (&ty.bounds, false),
        Type::TraitObject(ty) => (&ty.bounds, true),
        Type::Paren(ty) => return callback(&ty.elem, by_ref),
        _ => return Ok(None),
    };
    for bound in bounds {
        let TypeParamBound::Trait(bound) = bound else {
            continue;
        };
        let Some(last) = bound.path.segments.last() else {
            continue;
        };
        if !["Fn", "FnMut", "FnOnce"].iter().any(|f| last.ident == f) {
            continue;
        }
        let PathArguments::Parenthesized(arguments) = &last.arguments else {
            return Err(syn::Error::new(
                last.span(),
                "write the callback as `Fn(A, B) -> R`",
            ));
        };
        let output = match &arguments.output {
            ReturnType::Default => parse_quote! { () },
            ReturnType::Type(_, ty) => (**ty).clone(),
        };
        return Ok(Some(Callback {
            by_ref,
            arguments: arguments.inputs.iter().cloned().collect(),
            output,
            kind: last.ident.clone(),
            dynamic,
        }));
    }
    Ok(None)
}
