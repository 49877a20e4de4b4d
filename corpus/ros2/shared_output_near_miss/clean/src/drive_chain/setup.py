from setuptools import setup

package_name = "drive_chain"

setup(
    name=package_name,
    version="0.1.0",
    packages=[package_name],
    data_files=[("share/ament_index/resource_index/packages", ["resource/" + package_name]),
                ("share/" + package_name, ["package.xml"]),
                ("share/" + package_name + "/launch", ["launch/drive.launch.yaml"])],
    install_requires=["setuptools"],
    entry_points={"console_scripts": [
        "planner = drive_chain.planner:main",
        "smoother = drive_chain.smoother:main",
        "docker = drive_chain.docker:main",
        "recovery = drive_chain.recovery:main",
    ]},
)
