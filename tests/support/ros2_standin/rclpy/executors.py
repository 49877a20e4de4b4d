class SingleThreadedExecutor:
    def __init__(self, *, context=None):
        self.nodes = []

    def add_node(self, node):
        self.nodes.append(node)

    def spin(self):
        """The stand-in has no transport: nothing to wait for."""

    def shutdown(self):
        self.nodes = []
