"""Ports that a ROS library creates on its own, next to the one the code asks for: a
dynamic_reconfigure server's three, and image_transport's topic per transport plugin."""

from __future__ import annotations

from archlog import names

RECONFIGURE = (("publisher", "parameter_descriptions", "dynamic_reconfigure/ConfigDescription"),
               ("publisher", "parameter_updates", "dynamic_reconfigure/Config"),
               ("service_server", "set_parameters", "dynamic_reconfigure/Reconfigure"))

# The transports of image_transport_plugins (installed with ROS 1 desktop-full and perception):
# an image_transport publisher on TOPIC also advertises TOPIC/<transport>, and each transport's
# publisher runs a dynamic_reconfigure server in that namespace.
IMAGE_TRANSPORTS = (("compressed", "sensor_msgs/CompressedImage"),
                    ("compressedDepth", "sensor_msgs/CompressedImage"),
                    ("theora", "theora_image_transport/Packet"))


def reconfigure_ports(namespace: str) -> list[tuple[str, str, str]]:
    """(kind, name, type) of a dynamic_reconfigure server in `namespace`."""
    return [(kind, names.join(namespace, suffix) if namespace else suffix, type_) for kind, suffix, type_ in RECONFIGURE]


def image_transport_ports(topic: str) -> list[tuple[str, str, str]]:
    """(kind, name, type) of what an image_transport publisher on `topic` advertises besides it."""
    return [port for transport, type_ in IMAGE_TRANSPORTS
            for port in [("publisher", names.join(topic, transport), type_),
                         *reconfigure_ports(names.join(topic, transport))]]
