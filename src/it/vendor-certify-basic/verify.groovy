import groovy.json.JsonSlurper
def dir = new File(basedir, 'target/fclcert-reports')
['report.json', 'report.md', 'report.html', 'junit.xml', 'results.jsonl'].each {
    assert new File(dir, it).isFile() : "missing $it"
}
def report = new JsonSlurper().parse(new File(dir, 'report.json'))
assert report.iut.name == 'Vendor FCL'
assert report.basicLevel.conformant == true
def nsum = report.features.find { it.id == 'E-ACCU-NSUM' }
assert nsum.status == 'not-realised'
assert report.features.find { it.id == 'E-ACCU-BSUM' }.status == 'realised'
def log = new File(basedir, 'build.log').text
assert log.contains('meets failOn=basic')
assert log.contains('BUILD SUCCESS')
