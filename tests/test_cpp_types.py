"""Message types read from C++ spellings: a pcl::PointCloud<T> travels as sensor_msgs/PointCloud2
(pcl_ros's serialization), whatever its point type and however it is held."""

from __future__ import annotations

import pytest

from archlog.extract.cpp.clang_ast import type_from_spelling


@pytest.mark.parametrize(("spelling", "expected"), [
    ("pcl::PointCloud<pcl::Normal>", "sensor_msgs/PointCloud2"),
    ("const boost::shared_ptr<const pcl::PointCloud<pcl::PointXYZRGB> > &", "sensor_msgs/PointCloud2"),
    ("sensor_msgs::PointCloud2_<std::allocator<void> >", "sensor_msgs/PointCloud2"),
    ("pcl_msgs::PointIndices_<std::allocator<void> >", "pcl_msgs/PointIndices"),
])
def test_type_from_spelling(spelling: str, expected: str) -> None:
    assert type_from_spelling(spelling) == expected
