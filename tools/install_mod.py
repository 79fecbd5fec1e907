#!/usr/bin/env python3
"""meson install script: copy the library's Fortran .mod files to <prefix>/<moddir>.

meson has no built-in install rule for Fortran modules (dftd4 does the same).
"""
import os
import shutil
import sys
from pathlib import Path


def main() -> int:
    moddir = Path(sys.argv[1])
    build_root = Path(os.environ["MESON_BUILD_ROOT"])
    destdir = os.environ.get("DESTDIR", "")
    prefix = Path(os.environ["MESON_INSTALL_PREFIX"])
    target = moddir if moddir.is_absolute() else prefix / moddir
    if destdir:
        target = Path(destdir + str(target))
    target.mkdir(parents=True, exist_ok=True)
    mods = sorted({p.name: p for p in build_root.glob("libseispulse.*.p/seispulse*.mod")}.values())
    if not mods:
        print("install_mod: no seispulse*.mod under", build_root, file=sys.stderr)
        return 1
    for mod in mods:
        shutil.copy2(mod, target / mod.name)
    print(f"install_mod: {len(mods)} module files -> {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
