class Context:
    def __init__(self):
        self.domain_id = None

    def try_shutdown(self):
        self.domain_id = None
