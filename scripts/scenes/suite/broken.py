"""placeholder"""
def write_all(d):
    raise NotImplementedError
