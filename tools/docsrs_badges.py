"""Checks docs.rs's view of the crate: every impl that an optional feature
brings (derives included) carries rustdoc's "Available on crate feature"
badge. Reads the HTML that `cargo +nightly doc` writes with
`--cfg docsrs`, given as the doc directory of the crate.

An impl of the crate's own (not a blanket impl of another crate) belongs
to a feature when it is written in that feature's file
(`src/features/impl_<feature>.rs`), when it implements one of the traits
the feature derives or defines (serde's Serialize, bytemuck's Pod, defmt's
Format, approx's AbsDiffEq, ...), or when its header links to the
feature's crate.
"""

import pathlib
import re
import sys

FEATURE_CRATES = {
    "serde": ("serde", "serde_core"),
    "bytemuck": ("bytemuck",),
    "defmt": ("defmt",),
    "mint": ("mint",),
    "approx": ("approx",),
    "glam": ("glam",),
    "nalgebra": ("nalgebra",),
}

TRAITS = {
    "Serialize": "serde",
    "Deserialize": "serde",
    "Pod": "bytemuck",
    "Zeroable": "bytemuck",
    "Format": "defmt",
    "AbsDiffEq": "approx",
    "RelativeEq": "approx",
    "UlpsEq": "approx",
}

SOURCE = re.compile(r'href="[^"]*/features/impl_([a-z]+)\.rs\.html')
TRAIT = re.compile(r'<h3 class="code-header">impl(?:&lt;.*?&gt;)? (?:<a [^>]*>)?([A-Za-z]+)')
SECTION = re.compile(r'<section id="(impl-[^"]+)" class="impl">(.*?)</section>', re.S)
HEADER = re.compile(r'<h3 class="code-header">(.*?)</h3>', re.S)
BADGE = re.compile(r"Available on <strong>crate feature <code>([a-z0-9-]+)</code>")
# The features that bring another's impls: glam's, one per glam version.
SAME_AS = {"convert-glam030": "glam", "convert-glam032": "glam", "convert-glam033": "glam", "convert-glam034": "glam"}


def features_of(body, header):
    """The features the impl belongs to."""
    found = set(SOURCE.findall(body)) & set(FEATURE_CRATES)
    trait = TRAIT.search(body)
    if trait and trait.group(1) in TRAITS:
        found.add(TRAITS[trait.group(1)])
    for feature, crates in FEATURE_CRATES.items():
        for krate in crates:
            if re.search(rf'href="[^"]*/{krate}/[^"]*"|title="[a-z ]+ {krate}::', header):
                found.add(feature)
    return found


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: docsrs_badges.py <target/.../doc/rigtform>")
    root = pathlib.Path(sys.argv[1])
    pages = sorted(root.glob("struct.*.html")) + sorted(root.glob("enum.*.html"))
    if not pages:
        sys.exit(f"error: no struct or enum pages under {root}")
    checked, missing = 0, []
    for page in pages:
        html = page.read_text(encoding="utf-8")
        # The crate's own impls; the blanket impls of other crates
        # (`impl<T> DeserializeOwned for T`), listed last, are theirs.
        html = html.split('id="blanket-implementations"')[0]
        for impl_id, body in SECTION.findall(html):
            header = HEADER.search(body)
            if not header:
                continue
            needs = features_of(body, header.group(1))
            if not needs:
                continue
            checked += 1
            badges = {SAME_AS.get(b, b) for b in BADGE.findall(body)}
            if not needs & badges:
                missing.append(f"{page.name}#{impl_id}: needs {sorted(needs)}, badge {sorted(badges) or 'none'}")
    for line in missing:
        print("no feature badge:", line)
    print(f"{checked} feature-gated impls checked on {len(pages)} pages, {len(missing)} without their badge")
    if checked == 0:
        sys.exit("error: no feature-gated impl found: were the docs built with the features?")
    sys.exit(1 if missing else 0)


if __name__ == "__main__":
    main()
