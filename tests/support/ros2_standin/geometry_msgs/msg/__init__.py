from rosidl_standin import Message


class Vector3(Message):
    _fields_and_field_types = {"x": "double", "y": "double", "z": "double"}


class Twist(Message):
    _fields_and_field_types = {"linear": "geometry_msgs/Vector3", "angular": "geometry_msgs/Vector3"}


class Point(Message):
    _fields_and_field_types = {"x": "double", "y": "double", "z": "double"}


class Quaternion(Message):
    _fields_and_field_types = {"x": "double", "y": "double", "z": "double", "w": "double"}


class Pose(Message):
    _fields_and_field_types = {"position": "geometry_msgs/Point", "orientation": "geometry_msgs/Quaternion"}


class PoseWithCovariance(Message):
    _fields_and_field_types = {"pose": "geometry_msgs/Pose", "covariance": "double[36]"}


class PoseWithCovarianceStamped(Message):
    _fields_and_field_types = {"header": "std_msgs/Header", "pose": "geometry_msgs/PoseWithCovariance"}
