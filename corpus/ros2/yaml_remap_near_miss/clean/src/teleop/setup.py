from setuptools import setup

package_name = "teleop"

setup(
    name=package_name,
    version="0.1.0",
    packages=[package_name],
    data_files=[("share/ament_index/resource_index/packages", ["resource/" + package_name]),
                ("share/" + package_name, ["package.xml"]),
                ("share/" + package_name + "/launch", ["launch/teleop.launch.yaml"])],
    install_requires=["setuptools"],
    entry_points={"console_scripts": [
        "joystick_teleop = teleop.joystick_teleop:main",
        "velocity_smoother = teleop.velocity_smoother:main",
        "base_controller = teleop.base_controller:main",
    ]},
)
