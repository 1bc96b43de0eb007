def log = new File(basedir, 'build.log').text
assert log.contains('1 FCL file(s) checked')
assert log.contains('maxLevel basic: all conform')
assert log.contains('BUILD SUCCESS')
