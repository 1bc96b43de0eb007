import groovy.json.JsonSlurper
def report = new JsonSlurper().parse(new File(basedir, 'target/fclcert-reports/report.json'))
assert report.iut.command.contains('basic_iut.py')
assert report.basicLevel.conformant == true
assert report.summary.errored == 0
def log = new File(basedir, 'build.log').text
assert log.contains('meets failOn=basic')
