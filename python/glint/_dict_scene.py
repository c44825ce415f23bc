"""A scene given as a dict, written as glint's YAML with one key a line, so that an error the
loader reports at a line and column names the key of the dict it came from."""

import json
import math
from typing import Any, List, Tuple


def _scalar(value: Any, path: str) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return ".nan"
        if math.isinf(value):
            return ".inf" if value > 0 else "-.inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a double-quoted YAML string
    raise TypeError(f"{path or 'scene'}: expected a number, string, bool, list or dict, "
                    f"got {type(value).__name__}")


def _plain(value: Any) -> Any:
    """numpy arrays and scalars, tuples and paths as the plain values YAML holds."""
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, tuple):
        return list(value)
    if hasattr(value, "__fspath__"):
        return str(value.__fspath__())
    return value


def _is_flat(values: list) -> bool:
    return all(not isinstance(_plain(v), (dict, list)) for v in values)


def to_yaml(scene: dict) -> Tuple[str, List[str]]:
    """The YAML text of the scene and, for each of its lines, the dict path it holds
    ("materials.red.kd", "objects[2].center")."""
    if not isinstance(scene, dict):
        raise TypeError(f"scene: expected a dict, got {type(scene).__name__}")
    lines: List[str] = []
    paths: List[str] = []

    def emit(text: str, path: str) -> None:
        lines.append(text)
        paths.append(path)

    def value_text(value: Any, path: str) -> str:
        value = _plain(value)
        if isinstance(value, list) and _is_flat(value):
            return "[" + ", ".join(_scalar(_plain(v), f"{path}[{i}]")
                                   for i, v in enumerate(value)) + "]"
        if isinstance(value, dict) and not value:
            return "{}"
        return _scalar(value, path)

    def mapping(items: dict, indent: str, path: str, first_prefix: str = "") -> None:
        for n, (key, value) in enumerate(items.items()):
            if not isinstance(key, str):
                raise TypeError(f"{path or 'scene'}: keys must be strings, got {key!r}")
            key_path = f"{path}.{key}" if path else key
            prefix = first_prefix if n == 0 and first_prefix else indent
            block(prefix + json.dumps(key) + ":", value, indent, key_path)

    def block(head: str, value: Any, indent: str, path: str) -> None:
        value = _plain(value)
        if isinstance(value, dict) and value:
            emit(head, path)
            mapping(value, indent + "  ", path)
        elif isinstance(value, list) and not _is_flat(value):
            emit(head, path)
            for i, item in enumerate(value):
                item = _plain(item)
                item_path = f"{path}[{i}]"
                if isinstance(item, dict) and item:
                    mapping(item, indent + "    ", item_path, first_prefix=indent + "  - ")
                else:
                    emit(indent + "  - " + value_text(item, item_path), item_path)
        else:
            emit(head + " " + value_text(value, path), path)

    mapping(scene, "", "")
    return "\n".join(lines) + "\n", paths
