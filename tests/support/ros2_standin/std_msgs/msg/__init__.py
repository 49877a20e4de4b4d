from rosidl_standin import Message


class Header(Message):
    _fields_and_field_types = {"stamp": "builtin_interfaces/Time", "frame_id": "string"}
