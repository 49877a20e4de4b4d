from rosidl_standin import Message


class Time(Message):
    _fields_and_field_types = {"sec": "int32", "nanosec": "uint32"}


class Duration(Message):
    _fields_and_field_types = {"sec": "int32", "nanosec": "uint32"}
