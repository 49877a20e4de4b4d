from setuptools import setup

package_name = "rover_points"

setup(
    name=package_name,
    version="0.2.0",
    packages=[package_name],
    data_files=[("share/ament_index/resource_index/packages", ["resource/" + package_name]),
                ("share/" + package_name, ["package.xml"]),
                ("share/" + package_name + "/launch", ["launch/points.launch.py"])],
    install_requires=["setuptools"],
    entry_points={"console_scripts": [
        "points_driver = rover_points.points_driver:main",
        "cloud_monitor = rover_points.cloud_monitor:main",
    ]},
)
