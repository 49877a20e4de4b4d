from setuptools import setup

package_name = "rangers"

setup(
    name=package_name,
    version="0.1.0",
    packages=[package_name],
    data_files=[("share/ament_index/resource_index/packages", ["resource/" + package_name]),
                ("share/" + package_name, ["package.xml"]),
                ("share/" + package_name + "/launch", ["launch/rangers.launch.xml"])],
    install_requires=["setuptools"],
    entry_points={"console_scripts": [
        "ranger = rangers.ranger:main",
        "range_monitor = rangers.range_monitor:main",
    ]},
)
