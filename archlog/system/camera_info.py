"""image_transport's camera_info topics: a camera publisher or subscriber names its camera_info
topic after the image topic as it is *after* remapping (`image:=/camera/image_raw` moves the
camera_info topic to /camera/camera_info), so the sibling is placed per instance."""

from __future__ import annotations

from dataclasses import replace

from archlog import names
from archlog.extract.launch.model import LaunchNode
from archlog.extract.summary import Port


def placed_camera_info(port: Port, node: LaunchNode) -> Port:
    """A camera_info port named after its image topic as this instance resolves and remaps it."""
    image, handle = port.info_of, port.handle_ns
    if not isinstance(image, str) or not image or not isinstance(handle, str):
        return port
    if image.startswith(("/", "~")):
        resolved = names.resolve(image, node.namespace, node.name)
    else:
        resolved = names.join(names.resolve(handle, node.namespace, node.name) if handle else node.namespace, image)
    pairs = [(src, dst) for src, dst, _elem in node.remaps]
    remapped = names.remap(resolved, names.resolve_remaps(pairs[::-1] if node.ros2 else pairs, node.namespace,
                                                           node.name))
    return replace(port, name=names.join(names.namespace_of(remapped), "camera_info"), handle_ns="", info_of=None)
