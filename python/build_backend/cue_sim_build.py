"""The build backend of `pip install .` (PEP 517), with the standard library alone: nothing is
downloaded, so it builds where only Debian's archive is reachable.

It runs CMake on python/CMakeLists.txt (the module without ROS, the same libraries as the catkin
build), then packs the wheel: the package's Python files, the compiled cue_sim._core, and the
tables' URDF files and configuration it reads at run time (cue_sim/data).
"""
import base64
import hashlib
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig
import zipfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
NAME = "cue_sim"


def _version():
    return re.search(r"<version>([^<]+)</version>", (ROOT / "package.xml").read_text()).group(1)


def _tag():
    """The wheel's tag: this interpreter and this platform (the module is compiled for both)."""
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}-{platform}"


def _metadata():
    return (f"Metadata-Version: 2.1\nName: {NAME}\nVersion: {_version()}\n"
            "Summary: An exact, event-based pool table: the engine, games and learning environments, without ROS\n"
            "Requires-Python: >=3.9\nRequires-Dist: numpy\nLicense: BSD-3-Clause\n")


def _build(build_dir):
    """CMake's build of cue_sim._core for this interpreter; the files the wheel takes from it."""
    build_dir.mkdir(parents=True, exist_ok=True)
    jobs = str(os.cpu_count() or 1)
    print(f"cue_sim: building the module with CMake in {build_dir} ({jobs} jobs)", flush=True)
    subprocess.run(["cmake", "-S", str(ROOT / "python"), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                    f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
    subprocess.run(["cmake", "--build", str(build_dir), "--target", "cue_sim_python", "-j", jobs], check=True)
    modules = list(build_dir.glob("_core*.so"))
    if len(modules) != 1:
        raise RuntimeError(f"cue_sim: expected one _core module in {build_dir}, found {modules}")
    return modules[0], build_dir / "_built_for.py"


def _files(module, built_for):
    """(path in the wheel, path on disk) of everything the wheel holds."""
    package = ROOT / "python" / NAME
    for path in sorted(package.rglob("*.py")):
        if "__pycache__" not in path.parts:
            yield f"{NAME}/{path.relative_to(package).as_posix()}", path
    yield f"{NAME}/{module.name}", module
    yield f"{NAME}/_built_for.py", built_for
    for folder in ("urdf", "config"):
        for path in sorted((ROOT / folder).rglob("*")):
            if path.is_file():
                yield f"{NAME}/data/{folder}/{path.relative_to(ROOT / folder).as_posix()}", path


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build_dir = ROOT / "build" / f"wheel-{_tag()}"
    module, built_for = _build(build_dir)
    dist_info = f"{NAME}-{_version()}.dist-info"
    wheel_name = f"{NAME}-{_version()}-{_tag()}.whl"
    records = []
    with zipfile.ZipFile(pathlib.Path(wheel_directory) / wheel_name, "w", zipfile.ZIP_DEFLATED) as wheel:
        for name, path in _files(module, built_for):
            data = path.read_bytes()
            wheel.writestr(name, data)
            records.append(_record_line(name, data))
        meta = {f"{dist_info}/METADATA": _metadata().encode(),
                f"{dist_info}/WHEEL": (f"Wheel-Version: 1.0\nGenerator: cue_sim_build\nRoot-Is-Purelib: false\n"
                                       f"Tag: {_tag()}\n").encode()}
        for name, data in meta.items():
            wheel.writestr(name, data)
            records.append(_record_line(name, data))
        records.append(f"{dist_info}/RECORD,,")
        wheel.writestr(f"{dist_info}/RECORD", "\n".join(records) + "\n")
    return wheel_name


def build_sdist(sdist_directory, config_settings=None):
    """The repository's files that the wheel's build reads, as a source archive."""
    import tarfile
    base = f"{NAME}-{_version()}"
    name = f"{base}.tar.gz"
    keep = ["pyproject.toml", "package.xml", "CMakeLists.txt", "cmake", "include", "src", "python", "urdf", "config"]
    with tarfile.open(pathlib.Path(sdist_directory) / name, "w:gz") as archive:
        for item in keep:
            archive.add(ROOT / item, arcname=f"{base}/{item}",
                        filter=lambda info: None if "__pycache__" in info.name else info)
        pkg_info = _metadata().encode()
        import io
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        info.size = len(pkg_info)
        archive.addfile(info, io.BytesIO(pkg_info))
    return name


def clean(build_dir):  # pragma: no cover - a helper for a developer
    shutil.rmtree(build_dir, ignore_errors=True)
