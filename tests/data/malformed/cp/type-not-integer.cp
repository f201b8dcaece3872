mountain 0 0 100 100
