from setuptools import setup

package_name = "follow_me"

setup(
    name=package_name,
    version="0.1.0",
    packages=[package_name],
    data_files=[("share/ament_index/resource_index/packages", ["resource/" + package_name]),
                ("share/" + package_name, ["package.xml"]),
                ("share/" + package_name + "/launch", ["launch/follow.launch.py"]),
                ("share/" + package_name + "/config", ["config/follower.yaml"])],
    install_requires=["setuptools"],
    entry_points={"console_scripts": ["follower = follow_me.follower:main",
                                      "scan_filter = follow_me.scan_filter:main"]},
)
