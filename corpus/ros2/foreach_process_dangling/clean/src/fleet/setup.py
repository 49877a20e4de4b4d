from setuptools import setup

package_name = "fleet"

setup(
    name=package_name,
    version="0.1.0",
    packages=[package_name],
    data_files=[("share/ament_index/resource_index/packages", ["resource/" + package_name]),
                ("share/" + package_name, ["package.xml"]),
                ("share/" + package_name + "/launch", ["launch/fleet.launch.py"])],
    install_requires=["setuptools"],
    entry_points={"console_scripts": [
        "battery_monitor = fleet.battery_monitor:main",
        "dock_scheduler = fleet.dock_scheduler:main",
    ]},
)
